// The tree's layering, read from its sources: every project #include of a
// product, oracle or eval source (tests excluded) must point at its own
// module or at one the table below allows, so stages depend downward only
// and the oracle and eval sit beside the product. Headers keep third-party
// types out (Eigen and nlohmann::json excepted). The test prints the module
// graph it found.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace bespoke {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kScanners = {"scanners/core", "scanners/io", "scanners/render",
                                            "scanners/clean"};
const std::vector<std::string> kMeasure = {"measure/catalogue",     "measure/tape",
                                           "measure/mesh_geodesic", "measure/cloud_geodesic",
                                           "measure/landmarks",     "measure/measurements"};

std::set<std::string> Join(std::initializer_list<std::vector<std::string>> parts) {
  std::set<std::string> out;
  for (const auto& part : parts) out.insert(part.begin(), part.end());
  return out;
}

// Module -> the modules its sources may include (besides its own).
std::map<std::string, std::set<std::string>> AllowedDependencies() {
  const std::set<std::string> product = Join({kScanners, kMeasure, {"resize"}});
  std::map<std::string, std::set<std::string>> allowed = {
      {"scanners/core", {}},
      {"scanners/io", {"scanners/core"}},
      {"scanners/render", {"scanners/core"}},
      {"scanners/clean", {"scanners/core", "scanners/io"}},
      {"measure/catalogue", {"scanners/core"}},
      {"measure/tape", {"scanners/core"}},
      {"measure/mesh_geodesic", {"scanners/core"}},
      {"measure/cloud_geodesic", {"scanners/core", "measure/mesh_geodesic"}},
      {"measure/landmarks", Join({{"scanners/core"}, {kMeasure.begin(), kMeasure.begin() + 4}})},
      {"measure/measurements",
       Join({{"scanners/core", "scanners/render"}, {kMeasure.begin(), kMeasure.begin() + 5}})},
      {"resize", {"scanners/core", "scanners/io", "scanners/render", "measure/catalogue"}},
      {"pipeline/batch", product},
      {"oracle", Join({kScanners, {"measure/catalogue", "measure/tape"}})},
  };
  allowed["eval"] = Join({{product.begin(), product.end()}, {"oracle", "pipeline/batch"}});
  allowed["pipeline/cli"] = Join({{allowed["eval"].begin(), allowed["eval"].end()}, {"eval"}});
  return allowed;
}

// "scanners/io/ply.cc" -> "scanners/io"; "oracle/body/body.h" -> "oracle".
std::string ModuleOf(const std::string& path) {
  const std::string top = path.substr(0, path.find('/'));
  if (top == "oracle" || top == "eval" || top == "resize" || top == "tests") return top;
  const size_t second = path.find('/', top.size() + 1);
  return second == std::string::npos ? top : path.substr(0, second);
}

bool IsTestSource(const std::string& path) {
  return path.rfind("tests/", 0) == 0 || path.find("_test.cc") != std::string::npos;
}

struct Source {
  std::string path;  // relative to the repository root
  std::vector<std::string> project_includes, system_includes;
};

std::vector<Source> ReadSources(const fs::path& root) {
  const std::regex include_line(R"(^\s*#\s*include\s*([<"])([^">]+)[">])");
  std::vector<Source> sources;
  for (const char* top : {"scanners", "measure", "resize", "pipeline", "oracle", "eval"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".h" && ext != ".cc")) continue;
      Source source{fs::relative(entry.path(), root).generic_string(), {}, {}};
      std::ifstream in(entry.path());
      std::string line;
      std::smatch m;
      while (std::getline(in, line))
        if (std::regex_search(line, m, include_line))
          (m[1] == "\"" ? source.project_includes : source.system_includes).push_back(m[2]);
      sources.push_back(std::move(source));
    }
  }
  return sources;
}

TEST(Layering, EveryIncludeRunsDownwardOrSideways) {
  const fs::path root = BESPOKE_SOURCE_DIR;
  const auto allowed = AllowedDependencies();
  std::map<std::string, std::map<std::string, int>> graph;
  int checked = 0;
  for (const Source& source : ReadSources(root)) {
    if (IsTestSource(source.path)) continue;
    const std::string from = ModuleOf(source.path);
    ASSERT_TRUE(allowed.count(from))
        << source.path << ": module " << from << " is not in the table";
    for (const std::string& include : source.project_includes) {
      if (!fs::exists(root / include)) continue;  // generated or relative
      const std::string to = ModuleOf(include);
      ++checked;
      if (to == from) continue;
      ++graph[from][to];
      EXPECT_TRUE(allowed.at(from).count(to))
          << source.path << " includes " << include << ": " << from << " may not depend on " << to;
    }
  }
  EXPECT_GT(checked, 500);  // the walk found the tree
  std::ostringstream text;
  for (const auto& [from, tos] : graph) {
    text << "  " << from << " ->";
    for (const auto& [to, count] : tos) text << " " << to << " (" << count << ")";
    text << "\n";
  }
  std::cout << "module graph (includes per edge):\n" << text.str();
}

TEST(Layering, HeadersKeepThirdPartyTypesInTheirSources) {
  const std::regex heavy(
      R"(^(pcl|CGAL|open3d|opencv2|flann|cairo|tbb|oneapi|pagmo|spdlog|CLI|omp))");
  for (const Source& source : ReadSources(BESPOKE_SOURCE_DIR)) {
    if (source.path.size() < 2 || source.path.substr(source.path.size() - 2) != ".h") continue;
    for (const std::string& include : source.system_includes)
      EXPECT_FALSE(std::regex_search(include, heavy))
          << source.path << " includes <" << include << "> in a header";
  }
}

}  // namespace
}  // namespace bespoke
