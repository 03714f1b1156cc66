// Every app's --input: a rawlog in either MRPT layout, read object by object.
#include "FuzzInput.h"

#include <lvfusion/common/RawlogReader.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string& path = lvf::fuzz::inputFile(data, size, ".rawlog");
	lvf::fuzz::expectInputErrorOnly([&] {
		lvf::common::RawlogReader reader(path);
		while (reader.next()) {}
	});
	return 0;
}
