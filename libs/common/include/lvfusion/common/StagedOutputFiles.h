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

	/** Path to write `relativePath` to now (parent folders are created).
	 * InputError if it would leave the output folder (absolute, or with a
	 * ".." or "." part): commit() must never touch anything outside it. */
	std::string stage(const std::string& relativePath);

	/** Drops what was staged as `relativePath` (a file, or a folder with
	 * all it holds): commit() will not write it. */
	void withdraw(const std::string& relativePath);

	/** Final path `relativePath` will have after commit(). */
	std::string finalPath(const std::string& relativePath) const;

	/** Moves every staged top-level entry into the output folder (creating
	 * it if needed): a file replaces an older file of the same name, a
	 * folder is merged into a folder of the same name file by file. Such a
	 * folder is the run's (NAME_depth/, NAME_navlog/): its plain files with
	 * an extension this run wrote there, which this run did not replace, are
	 * taken for an earlier run's and removed (a file of that kind the user
	 * put there goes too); files of other kinds in it, anything else in the
	 * output folder, and a folder that is a link to elsewhere are never
	 * pruned. InputError naming the
	 * folder if that cannot be done (a file where a folder is, or the
	 * reverse). */
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

/** InputError for an output folder, given with `option`, that does not
 * exist yet and is named like a rawlog ("x.rawlog", "x.rawlog.gz"): MRPT's
 * tools take `-o OUT.rawlog`, ours `-o DIR`, and a folder of that name would
 * be made without a word. `hint` ends the message (where the file goes). */
void rejectRawlogNamedFolder(const std::string& outdir, const std::string& option, const std::string& hint);

/** Whether `name` can be the base name of output files: not empty, not "."
 * or "..", no '/' (names from the command line and world files end up as
 * `NAME.rawlog`, `NAME_poses.txt`, ... inside the output folder). */
bool isPlainFileName(const std::string& name);

/** The reason isPlainFileName rejects a name, for error messages. */
inline constexpr const char* kPlainFileNameRule =
	"must be a plain file name (it names the output files): not empty, no '/', not '.' or '..'";

}  // namespace lvf::common
