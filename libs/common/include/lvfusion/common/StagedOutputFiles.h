#pragma once
// "Never a half-written output": every file an app produces is first written
// into a hidden staging folder beside the output folder, and only moved into
// place by commit() once the whole run succeeded. If the object dies without
// commit() (an exception, a bad record), the staging folder is removed and the
// output folder is left exactly as it was.

#include <string>
#include <vector>

namespace lvf::common
{
class StagedOutputFiles
{
   public:
	explicit StagedOutputFiles(std::string outputDir);
	~StagedOutputFiles();
	StagedOutputFiles(const StagedOutputFiles&) = delete;
	StagedOutputFiles& operator=(const StagedOutputFiles&) = delete;

	/** Path to write `relativePath` to now (parent folders are created). */
	std::string stage(const std::string& relativePath);

	/** Final path `relativePath` will have after commit(). */
	std::string finalPath(const std::string& relativePath) const;

	/** Moves every staged top-level entry into the output folder (creating
	 * it if needed), replacing older files of the same name; InputError
	 * naming the folder if that cannot be done. */
	void commit();

	const std::string& outputDir() const { return m_outputDir; }

   private:
	std::string m_outputDir;
	std::string m_stagingDir;
	std::vector<std::string> m_topLevelEntries;
	bool m_committed = false;
};

/** `message` with the staging folders of this process's StagedOutputFiles
 * replaced by the output folders they stand for, so that an error about a
 * file being written names it where the user will look for it (runApp
 * prints every error through this). */
std::string withOutputPaths(std::string message);

}  // namespace lvf::common
