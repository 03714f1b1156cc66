#include <lvfusion/common/InputError.h>
#include <lvfusion/common/SignalCleanup.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/Suffixes.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <set>
#include <unistd.h>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace lvf::common
{
namespace
{
/** Every staging folder of this process and its output folder; a run
 * makes a handful, and an error may be printed after its object is gone. */
std::mutex stagingFoldersMutex;
std::vector<std::pair<std::string, std::string>> stagingFolders;

/** The first place where moving `from` to `to` would put a file where a
 * folder is, or a folder where a file is; empty if none. Checked for every
 * entry before any is moved, so that such a clash leaves the output folder
 * as it was. */
fs::path clashOf(const fs::path& from, const fs::path& to)
{
	if (!fs::exists(to)) return {};
	if (fs::is_directory(from) != fs::is_directory(to)) return to;
	if (!fs::is_directory(from)) return {};
	for (const fs::directory_entry& e : fs::directory_iterator(from))
		if (auto clash = clashOf(e.path(), to / e.path().filename()); !clash.empty()) return clash;
	return {};
}

/** In a folder of the run's (`to`, about to receive the files staged in
 * `from`), the files an earlier run wrote that this one does not replace:
 * plain files with an extension this run writes there (an earlier
 * `lvf-simulate -d` of more frames left NAME_depth/000005.pfm beside this
 * run's 000000.pfm). Files of other kinds, the user's, are not of the
 * run's. */
std::vector<fs::path> staleFilesIn(const fs::path& to, const fs::path& from)
{
	std::set<fs::path> written, kinds;
	for (const fs::directory_entry& e : fs::directory_iterator(from))
		if (e.is_regular_file())
		{
			written.insert(e.path().filename());
			// A name without an extension says nothing of its kind.
			if (e.path().has_extension()) kinds.insert(e.path().extension());
		}
	std::vector<fs::path> stale;
	for (const fs::directory_entry& e : fs::directory_iterator(to))
		if (fs::is_regular_file(e.symlink_status()) && !written.count(e.path().filename()) &&
			kinds.count(e.path().extension()))
			stale.push_back(e.path());
	return stale;
}

/** Moves `from` to `to`: a file replaces a file of that name, a folder is
 * merged entry by entry into a folder of that name, whose stale files of the
 * run's kinds go (staleFilesIn; what else it holds stays). A folder of that
 * name that is a link to another place is merged into but never pruned:
 * what it points to is not the run's. */
void moveInto(const fs::path& from, const fs::path& to)
{
	if (fs::is_directory(from) && fs::is_directory(to))
	{
		if (!fs::is_symlink(to))
			for (const fs::path& stale : staleFilesIn(to, from)) fs::remove(stale);
		for (const fs::directory_entry& e : fs::directory_iterator(from))
			moveInto(e.path(), to / e.path().filename());
		return;
	}
	fs::rename(from, to);
}

/** InputError unless `relativePath` stays inside the folder it is taken in:
 * not empty, not absolute, no ".." or "." part. */
void requireInside(const fs::path& relativePath, const std::string& shownAs)
{
	const bool leaves = relativePath.empty() || relativePath.is_absolute() ||
		std::any_of(relativePath.begin(), relativePath.end(), [](const fs::path& part) { return part == ".." || part == "."; });
	if (leaves) throw InputError(shownAs, "", "an output must lie inside the output folder");
}
}  // namespace

void rejectRawlogNamedFolder(const std::string& outdir, const std::string& option, const std::string& hint)
{
	if ((endsWith(outdir, ".rawlog") || endsWith(outdir, ".rawlog.gz")) && !fs::is_directory(outdir))
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
	// before the run's work rather than after it (and registered first, so
	// that a signal in between finds it).
	removeOnSignal(m_stagingDir);
	std::error_code ec;
	fs::create_directories(m_stagingDir, ec);
	if (ec) throw InputError(m_outputDir, "", "cannot write the outputs here: " + ec.message());
	const std::lock_guard<std::mutex> lock(stagingFoldersMutex);
	stagingFolders.emplace_back((fs::path(m_stagingDir) / "").string(), (fs::path(m_outputDir) / "").string());
}

StagedOutputFiles::~StagedOutputFiles()
{
	std::error_code ignored;
	fs::remove_all(m_stagingDir, ignored);
	keepOnSignal(m_stagingDir);
}

std::string StagedOutputFiles::stage(const std::string& relativePath)
{
	const fs::path rel(relativePath);
	requireInside(rel, finalPath(relativePath));
	const std::string top = rel.begin()->string();
	if (std::find(m_topLevelEntries.begin(), m_topLevelEntries.end(), top) ==
		m_topLevelEntries.end())
		m_topLevelEntries.push_back(top);
	const fs::path p = fs::path(m_stagingDir) / rel;
	// Below the staging folder only: if a signal has just removed it, it is
	// not made again (the process is ending).
	if (p.parent_path() != fs::path(m_stagingDir) && fs::is_directory(m_stagingDir))
		fs::create_directories(p.parent_path());
	return p.string();
}

void StagedOutputFiles::withdraw(const std::string& relativePath)
{
	requireInside(relativePath, finalPath(relativePath));
	std::error_code ignored;
	fs::remove_all(fs::path(m_stagingDir) / relativePath, ignored);
}

std::string StagedOutputFiles::finalPath(const std::string& relativePath) const
{
	return (fs::path(m_outputDir) / relativePath).string();
}

void StagedOutputFiles::commit()
{
	const auto notKilledMeanwhile = holdOffSignalCleanup();
	try
	{
		std::vector<std::pair<fs::path, fs::path>> moves;  // staged, then dropped (withdraw): none
		for (const auto& entry : m_topLevelEntries)
			if (const fs::path from = fs::path(m_stagingDir) / entry; fs::exists(from))
				moves.emplace_back(from, fs::path(m_outputDir) / entry);
		for (const auto& [from, to] : moves)
			if (const fs::path clash = clashOf(from, to); !clash.empty())
				throw InputError(m_outputDir, "", "cannot move the outputs into place: " + clash.string() + " is " +
						(fs::is_directory(clash) ? "a folder, where this run wrote a file" : "a file, where this run wrote a folder"));
		fs::create_directories(m_outputDir);
		for (const auto& [from, to] : moves) moveInto(from, to);
	}
	catch (const fs::filesystem_error& e)
	{
		const std::string where = e.path1().empty() ? "" : " (" + e.path1().string() + ")";
		throw InputError(m_outputDir, "", "cannot move the outputs into place: " + e.code().message() + where);
	}
	m_committed = true;
}

}  // namespace lvf::common
