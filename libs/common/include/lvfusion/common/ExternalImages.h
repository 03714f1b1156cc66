#pragma once
// Rawlogs from real robots keep their camera images as files beside the log
// (MRPT's "external storage": rawlog-grabber's default, rawlog-edit
// --externalize), the observation holding only the file's name, relative to
// the folder NAME_Images beside NAME.rawlog. MRPT resolves such names
// against one process-wide folder (CImage::setImagesPathBase); here each
// image is pointed at its file's absolute path once, when the log is read,
// so that the images load from any working directory and a rawlog written
// from these observations still finds them.

#include <mrpt/serialization/CSerializable.h>

#include <string>

namespace lvf::common
{
/** The folder a rawlog's external images are in, by MRPT's convention:
 * NAME_Images (or NAME_images, NAME_IMAGES) beside NAME.rawlog if it
 * exists, else Images beside it. Written here because MRPT 2.5.8's
 * CRawlog::detectImagesDirectory drops the separator after the folder of a
 * path that has one ("logs/a.rawlog" -> "logsImages"). */
std::string externalImagesDirectory(const std::string& rawlogPath);

/** Points every externally stored image of the entry's CObservationImage
 * and CObservationStereoImages observations (in a sensory frame too) at
 * its file's absolute path in `folder` (the log's images folder, relative
 * to the working directory or absolute); names that are absolute already
 * stay. Loads nothing. Returns how many images are externally stored. */
size_t anchorExternalImages(const mrpt::serialization::CSerializable::Ptr& entry, const std::string& folder);

}  // namespace lvf::common
