#pragma once

namespace lvf
{
/** Registers every MRPT class of lvfusion (idempotent). Apps that create
 * lvfusion classes by name call it once at start-up; the plugin calls it
 * when MRPT loads it. */
void registerAllClasses();
}  // namespace lvf
