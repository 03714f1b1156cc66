#pragma once
// lvf-bench on real images: the Middlebury 2014 scenes that show a floor
// (lvf::middlebury::importScene, as lvf-import-middlebury makes them), each
// one frame, through the fusion and the two dense matchers: time per frame
// and recall / phantom rate / range error of each, per scene.

#include <string>

namespace lvf::bench
{
/** Every scene folder under `root`; those without a visible floor are named
 * as skipped. Prints one line saying so when `root` holds no scene. */
void printRealScenes(const std::string& root, int passes);
}  // namespace lvf::bench
