#pragma once
// The numbers of MRPT's pf-localization sections that lvf-map hands to MRPT,
// checked against what they mean before the run. MRPT's own loaders read
// them without a range (a KLD bin of 0 m, a BETA of nan, a likelihood method
// of 99, a noise floor of -1 m are all taken, and the filter then runs on
// nonsense without a word), so a value out of range is refused here: one line
// naming the file, section and key.

#include <mrpt/config/CConfigFileBase.h>

namespace lvf::apps
{
/** The most particles any of the filter's counts may ask for. */
constexpr int kMostParticles = 10000000;

/** `user`: the file as written (errors name it); `merged`: the defaults with
 * it over them (for rules across keys). Throws lvf::common::InputError. */
void requireUsablePfOptions(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged);

}  // namespace lvf::apps
