// Entry point of the plugin liblvfusion.so: MRPT tools load it with
// `-l liblvfusion.so` (RawLogViewer, navlog-viewer) or `--plugins` (rawlog-edit)
// and this initializer makes every lvfusion class known by name.

#include <lvfusion/plugin/registerAllClasses.h>
#include <mrpt/core/initializer.h>

MRPT_INITIALIZER(lvfusion_plugin_register) { lvf::registerAllClasses(); }
