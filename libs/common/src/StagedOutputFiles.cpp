#include <lvfusion/common/InputError.h>
#include <lvfusion/common/StagedOutputFiles.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lvf::common
{
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
}

StagedOutputFiles::~StagedOutputFiles()
{
	std::error_code ignored;
	fs::remove_all(m_stagingDir, ignored);
}

std::string StagedOutputFiles::stage(const std::string& relativePath)
{
	const fs::path rel(relativePath);
	const std::string top = rel.begin()->string();
	if (std::find(m_topLevelEntries.begin(), m_topLevelEntries.end(), top) ==
		m_topLevelEntries.end())
		m_topLevelEntries.push_back(top);
	const fs::path p = fs::path(m_stagingDir) / rel;
	fs::create_directories(p.parent_path());
	return p.string();
}

std::string StagedOutputFiles::finalPath(const std::string& relativePath) const
{
	return (fs::path(m_outputDir) / relativePath).string();
}

void StagedOutputFiles::commit()
{
	fs::create_directories(m_outputDir);
	for (const auto& entry : m_topLevelEntries)
	{
		const fs::path from = fs::path(m_stagingDir) / entry;
		const fs::path to = fs::path(m_outputDir) / entry;
		if (fs::is_directory(to)) fs::remove_all(to);
		fs::rename(from, to);
	}
	m_committed = true;
}

}  // namespace lvf::common
