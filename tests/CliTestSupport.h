#pragma once
// Running lvfusion's programs as a user does, from tests: each test gets its
// own empty working folder, and a run's exit status, stdout and stderr.

#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

namespace lvf::test
{
namespace fs = std::filesystem;

struct RunResult
{
	int status = -1;
	std::string out, err;
};

inline std::string slurp(const fs::path& p)
{
	std::ifstream in(p);
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

class CliTest : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		m_dir = fs::temp_directory_path() /
			("lvf_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
			 std::to_string(::getpid()));  // two builds' suites may run at once
		fs::remove_all(m_dir);
		fs::create_directories(m_dir);
	}
	void TearDown() override { fs::remove_all(m_dir); }

	/** Runs `program args` in the test's folder, no standard input. */
	RunResult run(const std::string& program, const std::string& args) const
	{
		const fs::path out = m_dir / "stdout.txt", err = m_dir / "stderr.txt";
		const std::string cmd = "cd '" + m_dir.string() + "' && '" + program + "' " + args +
			" >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
		const int raw = std::system(cmd.c_str());
		RunResult r;
		r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
		r.out = slurp(out);
		r.err = slurp(err);
		return r;
	}

	fs::path write(const std::string& name, const std::string& text) const
	{
		std::ofstream(m_dir / name) << text;
		return m_dir / name;
	}

	fs::path m_dir;
};

/** label -> count, from rawlog-edit --info. */
inline std::map<std::string, int> labelCounts(const std::string& info)
{
	std::map<std::string, int> counts;
	const std::regex row(R"(Sensor \(Label/Occurs/Rate/Durat\.\)\s*:\s*(\S+)\s*/\s*(\d+))");
	for (std::sregex_iterator it(info.begin(), info.end(), row), end; it != end; ++it)
		counts[(*it)[1]] = std::stoi((*it)[2]);
	return counts;
}

/** A CSV file with a header line: one column name -> field map per row. */
inline std::vector<std::map<std::string, std::string>> readCsv(const fs::path& p)
{
	auto fields = [](const std::string& line) {
		std::vector<std::string> out;
		std::stringstream in(line);
		for (std::string f; std::getline(in, f, ',');) out.push_back(f);
		if (!line.empty() && line.back() == ',') out.push_back("");
		return out;
	};
	std::istringstream in(slurp(p));
	std::string line;
	std::getline(in, line);
	const auto header = fields(line);
	std::vector<std::map<std::string, std::string>> rows;
	while (std::getline(in, line))
	{
		const auto values = fields(line);
		auto& row = rows.emplace_back();
		for (size_t k = 0; k < header.size(); k++) row[header[k]] = k < values.size() ? values[k] : "";
	}
	return rows;
}

/** Lines of `text` that are not blank nor comments (# ;). */
inline std::vector<std::string> keyLines(const std::string& text)
{
	std::vector<std::string> lines;
	std::istringstream in(text);
	for (std::string l; std::getline(in, l);)
		if (!l.empty() && l[0] != '#' && l[0] != ';') lines.push_back(l);
	return lines;
}

}  // namespace lvf::test
