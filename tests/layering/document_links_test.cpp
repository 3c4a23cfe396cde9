// The README and docs/ link only files inside the repository, and every one of them exists: a
// reader who clones the repository alone can follow every link.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> pages() {
  const fs::path root = QR_SOURCE_DIR;
  std::vector<fs::path> out = {root / "README.md"};
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string rel = fs::relative(entry.path(), root).generic_string();
    if (rel.rfind("build", 0) == 0 || rel.rfind(".git", 0) == 0) continue;
    if (entry.path().extension() == ".md" && entry.path() != root / "README.md") out.push_back(entry.path());
  }
  return out;
}

TEST(DocumentLinks, EveryLinkIsAFileOfTheRepository) {
  const fs::path root = fs::weakly_canonical(QR_SOURCE_DIR);
  const std::regex link(R"(\]\(([^)\s]+)\))");
  int checked = 0;
  for (const fs::path& page : pages()) {
    const std::string text = read(page);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
      std::string target = (*it)[1].str();
      if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 || target[0] == '#') continue;
      target.resize(std::min(target.size(), target.find('#')));
      const fs::path resolved = fs::weakly_canonical(page.parent_path() / target);
      const std::string rel = fs::relative(resolved, root).generic_string();
      EXPECT_FALSE(rel.rfind("..", 0) == 0) << page << " links outside the repository: " << target;
      EXPECT_TRUE(fs::exists(resolved)) << page << " links a missing file: " << target;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20) << "the pages were read";
}

TEST(DocumentLinks, TheReadmeNamesNoFileOutsideTheRepository) {
  const std::string readme = read(fs::path(QR_SOURCE_DIR) / "README.md");
  EXPECT_EQ(readme.find("../"), std::string::npos) << "README.md points outside the repository";
}

}  // namespace
