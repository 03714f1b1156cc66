#include <lvfusion/common/ShippedFiles.h>

#include <filesystem>
#include <system_error>

namespace lvf::common
{
std::string shippedFile(const std::string& installed, const std::string& inSourceTree)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	// Linux names the running program's file here; no such link, no install.
	const fs::path program = fs::read_symlink("/proc/self/exe", ec);
	if (ec) return inSourceTree;
	const fs::path candidate = (program.parent_path() / LVF_SHARE_FROM_BIN / installed).lexically_normal();
	return fs::is_regular_file(candidate, ec) ? candidate.string() : inSourceTree;
}
}  // namespace lvf::common
