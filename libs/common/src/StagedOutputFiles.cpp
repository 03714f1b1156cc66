#include <lvfusion/common/StagedOutputFiles.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lvf::common
{
StagedOutputFiles::StagedOutputFiles(std::string outputDir)
	: m_outputDir(std::move(outputDir))
{
	fs::path out(m_outputDir);
	if (out.filename().empty()) out = out.parent_path();  // "dir/" -> "dir"
	// Beside the output folder, so that commit() is a same-filesystem rename.
	m_stagingDir = (out.parent_path() /
					("." + out.filename().string() + ".partial-" +
					 std::to_string(::getpid())))
					   .string();
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
