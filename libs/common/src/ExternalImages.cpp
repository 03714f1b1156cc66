#include <lvfusion/common/ExternalImages.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace lvf::common
{
std::string externalImagesDirectory(const std::string& rawlogPath)
{
	const fs::path log(rawlogPath);
	const fs::path folder = log.parent_path();
	for (const char* suffix : {"_Images", "_images", "_IMAGES"})
	{
		const fs::path candidate = folder / (log.stem().string() + suffix);
		if (fs::is_directory(candidate)) return candidate.string();
	}
	return (folder / "Images").string();
}

namespace
{
/** Calls f on every image an observation may hold as a file. */
template <typename F>
void forEachImage(const mrpt::obs::CObservation::Ptr& o, F&& f)
{
	if (auto single = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(o)) f(single->image);
	else if (auto stereo = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o))
	{
		f(stereo->imageLeft);
		if (stereo->hasImageRight) f(stereo->imageRight);
		if (stereo->hasImageDisparity) f(stereo->imageDisparity);
	}
}
}  // namespace

size_t anchorExternalImages(const mrpt::serialization::CSerializable::Ptr& entry, const std::string& folder)
{
	const fs::path absoluteFolder = fs::absolute(folder);
	size_t count = 0;
	auto anchor = [&](mrpt::img::CImage& image) {
		if (!image.isExternallyStored()) return;
		count++;
		const fs::path name(image.getExternalStorageFile());
		if (name.is_relative()) image.setExternalStorage((absoluteFolder / name).lexically_normal().string());
	};
	if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(entry))
		for (const auto& o : *sf) forEachImage(o, anchor);
	else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(entry))
		forEachImage(o, anchor);
	return count;
}

}  // namespace lvf::common
