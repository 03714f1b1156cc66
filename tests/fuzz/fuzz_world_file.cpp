// lvf-simulate / lvf-navigate --world: the YAML world description.
#include "FuzzInput.h"

#include <lvfusion/simulation/WorldLoader.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string text(reinterpret_cast<const char*>(data), size);
	lvf::fuzz::expectInputErrorOnly([&] { lvf::simulation::parseWorld(text, "fuzz.yaml"); });
	return 0;
}
