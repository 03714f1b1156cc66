#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RemovedIfKilled.h>
#include <lvfusion/common/StagedOutputFiles.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <unistd.h>
#include <utility>

namespace fs = std::filesystem;

namespace lvf::common
{
namespace
{
/** Every staging folder of this process and its output folder; a run
 * makes a handful, and an error may be printed after its object is gone. */
std::mutex stagingFoldersMutex;
std::vector<std::pair<std::string, std::string>> stagingFolders;

/** Moves `from` to `to`: a file replaces a file of that name, a folder is
 * merged entry by entry into a folder of that name (what else it holds, not
 * this run's, stays). A file where a folder is, or the reverse, throws. */
void moveInto(const fs::path& from, const fs::path& to)
{
	if (fs::is_directory(from) && fs::is_directory(to))
	{
		for (const fs::directory_entry& e : fs::directory_iterator(from))
			moveInto(e.path(), to / e.path().filename());
		return;
	}
	if (fs::is_directory(to))
		throw fs::filesystem_error("", to, std::make_error_code(std::errc::is_a_directory));
	fs::rename(from, to);
}
}  // namespace

void rejectRawlogNamedFolder(const std::string& outdir, const std::string& option, const std::string& hint)
{
	const auto endsWith = [&](const std::string& end) {
		return outdir.size() >= end.size() && outdir.compare(outdir.size() - end.size(), end.size(), end) == 0;
	};
	if ((endsWith(".rawlog") || endsWith(".rawlog.gz")) && !fs::is_directory(outdir))
		throw InputError(option, "", "'" + outdir + "' is named like a rawlog, but names the output folder; " + hint);
}

bool isPlainFileName(const std::string& name)
{
	return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

std::string withOutputPaths(std::string message)
{
	const std::lock_guard<std::mutex> lock(stagingFoldersMutex);
	for (const auto& [staging, output] : stagingFolders)
		for (size_t at = message.find(staging); at != std::string::npos; at = message.find(staging, at + output.size()))
			message.replace(at, staging.size(), output);
	return message;
}

StagedOutputFiles::StagedOutputFiles(std::string outputDir)
	: m_outputDir(outputDir.empty() ? "." : std::move(outputDir))  // "" from a bare file name's folder
{
	if (fs::exists(m_outputDir) && !fs::is_directory(m_outputDir))
		throw InputError(m_outputDir, "", "exists and is not a folder (the outputs go into a folder)");
	// Absolute and normal, so that "." and "dir/" have a name and a parent.
	fs::path out = fs::absolute(m_outputDir).lexically_normal();
	if (out.filename().empty()) out = out.parent_path();  // "dir/" -> "dir"
	// On the output folder's filesystem, so that commit() is a rename: inside
	// it if it exists (its parent need not be writable: the current folder,
	// a home folder), else beside it, where it is to be made.
	const std::string pid = std::to_string(::getpid());
	m_stagingDir = (fs::is_directory(out) ? out / (".lvf-partial-" + pid)
										  : out.parent_path() / ("." + out.filename().string() + ".partial-" + pid))
					   .string();
	// Made now, so that an output folder that cannot be made is reported
	// before the run's work rather than after it.
	std::error_code ec;
	fs::create_directories(m_stagingDir, ec);
	if (ec) throw InputError(m_outputDir, "", "cannot write the outputs here: " + ec.message());
	removeIfKilled(m_stagingDir);
	const std::lock_guard<std::mutex> lock(stagingFoldersMutex);
	stagingFolders.emplace_back((fs::path(m_stagingDir) / "").string(), (fs::path(m_outputDir) / "").string());
}

StagedOutputFiles::~StagedOutputFiles()
{
	std::error_code ignored;
	fs::remove_all(m_stagingDir, ignored);
}

std::string StagedOutputFiles::stage(const std::string& relativePath)
{
	const fs::path rel(relativePath);
	const bool leaves = rel.empty() || rel.is_absolute() ||
		std::any_of(rel.begin(), rel.end(), [](const fs::path& part) { return part == ".." || part == "."; });
	if (leaves) throw InputError(finalPath(relativePath), "", "an output must lie inside the output folder");
	const std::string top = rel.begin()->string();
	if (std::find(m_topLevelEntries.begin(), m_topLevelEntries.end(), top) ==
		m_topLevelEntries.end())
		m_topLevelEntries.push_back(top);
	const fs::path p = fs::path(m_stagingDir) / rel;
	fs::create_directories(p.parent_path());
	return p.string();
}

void StagedOutputFiles::withdraw(const std::string& relativePath)
{
	std::error_code ignored;
	fs::remove_all(fs::path(m_stagingDir) / relativePath, ignored);
}

std::string StagedOutputFiles::finalPath(const std::string& relativePath) const
{
	return (fs::path(m_outputDir) / relativePath).string();
}

void StagedOutputFiles::commit()
{
	try
	{
		fs::create_directories(m_outputDir);
		for (const auto& entry : m_topLevelEntries)
		{
			const fs::path from = fs::path(m_stagingDir) / entry;
			if (!fs::exists(from)) continue;  // staged, then dropped (withdraw)
			moveInto(from, fs::path(m_outputDir) / entry);
		}
	}
	catch (const fs::filesystem_error& e)
	{
		const std::string where = e.path1().empty() ? "" : " (" + e.path1().string() + ")";
		throw InputError(m_outputDir, "", "cannot move the outputs into place: " + e.code().message() + where);
	}
	m_committed = true;
}

}  // namespace lvf::common
