#include "pipeline/batch/scan_list.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>

#include "scanners/core/errors.h"

namespace bespoke {
namespace fs = std::filesystem;
namespace {

bool IsIdChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ||
         c == '+';
}

std::string SanitizeId(const std::string& raw) {
  std::string id;
  for (char c : raw) id += IsIdChar(c) ? c : '_';
  if (id.empty() || id[0] == '.') id = "_" + id;
  return id;
}

// Bespoke's atomic writer leaves "<name>.tmp-<pid>-<n>" behind only when killed.
bool IsTempName(const std::string& name) { return name.find(".tmp-") != std::string::npos; }

fs::path Absolute(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal();
}

void Walk(const DiscoverOptions& options, const fs::path& root, const fs::path& dir,
          std::vector<fs::path>* found) {
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) throw InputError(dir, "cannot list folder: " + ec.message());
  for (const fs::directory_entry& entry : it) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || IsTempName(name)) continue;
    if (HasScanExtension(entry.path())) {
      found->push_back(entry.path().lexically_relative(root));
      continue;
    }
    if (!options.recursive || entry.is_symlink(ec) || !entry.is_directory(ec)) continue;
    if (!options.exclude.empty() && fs::equivalent(entry.path(), options.exclude, ec)) continue;
    Walk(options, root, entry.path(), found);
  }
}

}  // namespace

bool HasScanExtension(const fs::path& path) {
  static const std::set<std::string> kExtensions = {".ply", ".pcd", ".obj", ".xyz", ".csv", ".txt"};
  return kExtensions.count(AsciiLower(path.extension().string())) > 0;
}

std::vector<ScanEntry> DiscoverScans(const DiscoverOptions& options, const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir, "is not a folder");
  const fs::path root = Absolute(dir);
  std::vector<fs::path> relative;
  Walk(options, root, root, &relative);
  std::sort(relative.begin(), relative.end());

  // First choice: the relative path without extension; on a clash, with it.
  auto base_id = [](const fs::path& rel, bool with_extension) {
    std::string stem = (rel.parent_path() / rel.stem()).generic_string();
    std::string id;
    for (size_t i = 0; i < stem.size(); ++i)
      id += stem[i] == '/' ? std::string("__") : std::string(1, stem[i]);
    if (with_extension) id += "_" + AsciiLower(rel.extension().string().substr(1));
    return SanitizeId(id);
  };
  std::map<std::string, int> first_choice;
  for (const fs::path& rel : relative) ++first_choice[base_id(rel, false)];
  std::vector<ScanEntry> scans;
  std::map<std::string, int> used;
  for (const fs::path& rel : relative) {
    std::string id = base_id(rel, first_choice[base_id(rel, false)] > 1);
    const int n = ++used[id];
    if (n > 1) id += "-" + std::to_string(n);
    scans.push_back({id, root / rel, "", "", {}});
  }
  std::sort(scans.begin(), scans.end(),
            [](const ScanEntry& a, const ScanEntry& b) { return a.id < b.id; });
  return scans;
}

std::vector<ScanEntry> ReadManifest(const fs::path& manifest) {
  const std::vector<CsvRecord> records = ReadCsvRecords(manifest);
  if (records.empty()) throw InputError(manifest, "empty manifest (no header line)");
  const fs::path base = Absolute(manifest).parent_path();
  const CsvColumns columns(records[0]);
  if (!columns.Has("id") || !columns.Has("path")) {
    throw InputError(manifest, "line " + std::to_string(records[0].line) +
                                   ": the header must name the columns 'id' and 'path'");
  }
  std::vector<ScanEntry> scans;
  std::map<std::string, int> id_line;
  for (size_t r = 1; r < records.size(); ++r) {
    const CsvRecord& record = records[r];
    const std::string where = "line " + std::to_string(record.line) + ": ";
    ScanEntry entry{columns.Field(record, "id"),
                    {},
                    columns.Field(record, "design"),
                    columns.Field(record, "units"),
                    {}};
    const std::string path = columns.Field(record, "path");
    if (entry.id.empty() || path.empty()) throw InputError(manifest, where + "empty id or path");
    if (entry.id[0] == '.' || !std::all_of(entry.id.begin(), entry.id.end(), IsIdChar)) {
      throw InputError(manifest, where + "id '" + entry.id +
                                     "' may use only letters, digits and . _ + - (not first .)");
    }
    if (id_line.count(entry.id)) {
      throw InputError(manifest, where + "id '" + entry.id + "' repeats line " +
                                     std::to_string(id_line[entry.id]));
    }
    id_line[entry.id] = record.line;
    entry.path = fs::path(path).is_absolute() ? fs::path(path).lexically_normal()
                                              : (base / path).lexically_normal();
    if (const std::string lm = columns.Field(record, "landmarks"); !lm.empty()) {
      entry.landmarks = fs::path(lm).is_absolute() ? fs::path(lm) : (base / lm).lexically_normal();
    }
    scans.push_back(std::move(entry));
  }
  std::sort(scans.begin(), scans.end(),
            [](const ScanEntry& a, const ScanEntry& b) { return a.id < b.id; });
  return scans;
}

std::vector<ScanEntry> ListScans(const DiscoverOptions& options, const fs::path& input) {
  std::error_code ec;
  if (fs::is_directory(input, ec)) return DiscoverScans(options, input);
  if (!fs::exists(input, ec)) throw InputError(input, "no such folder or manifest");
  return ReadManifest(input);
}

std::string Shard::ToString() const { return std::to_string(index) + "/" + std::to_string(count); }

std::string Shard::DirName() const {
  return "shard-" + std::to_string(index) + "-of-" + std::to_string(count);
}

Shard ParseShard(const std::string& text) {
  const size_t slash = text.find('/');
  Shard shard;
  try {
    size_t used_i = 0, used_n = 0;
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    shard.index = std::stoi(text.substr(0, slash), &used_i);
    shard.count = std::stoi(text.substr(slash + 1), &used_n);
    if (used_i != slash || used_n != text.size() - slash - 1) throw std::invalid_argument("junk");
  } catch (const std::exception&) {
    throw InputError("--shard '" + text + "': expected I/N, e.g. 2/4");
  }
  if (shard.count < 1 || shard.count > 100000 || shard.index < 1 || shard.index > shard.count) {
    throw InputError("--shard '" + text + "': need 1 <= I <= N <= 100000");
  }
  return shard;
}

std::vector<ScanEntry> SelectShard(const std::vector<ScanEntry>& sorted_scans, const Shard& shard) {
  std::vector<ScanEntry> selected;
  for (size_t p = 0; p < sorted_scans.size(); ++p) {
    if (static_cast<int>(p % shard.count) == shard.index - 1) selected.push_back(sorted_scans[p]);
  }
  return selected;
}

}  // namespace bespoke
