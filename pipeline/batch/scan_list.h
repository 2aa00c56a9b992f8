// Which scans a batch processes: discovery in a folder or a manifest CSV, ids,
// and the stable split into shards.
//
// Discovery: every entry of INPUT_DIR (and its sub-folders with `recursive`)
// whose name ends in .ply .pcd .obj .xyz .csv .txt (any case), whatever it is:
// a regular file, a symlink (also a dangling one), a folder named like a scan,
// a FIFO. Entries that are not readable scans are kept on purpose so that the
// batch lists them as failures with a reason instead of silently skipping
// them. Hidden entries (".name") and Bespoke's own temporary files are skipped.
//
// Ids: the path relative to INPUT_DIR without the extension, "/" replaced by
// "__", characters outside [A-Za-z0-9._+-] replaced by "_". When two scans
// would get the same id ("a.ply" and "a.pcd") both get the extension appended
// ("a_ply", "a_pcd"); remaining clashes get "-2", "-3" in path order.
//
// Manifest: a CSV file (csv.h) with a header naming the columns;
// `id` and `path` are required, `design`, `units` and `landmarks` optional,
// other columns are ignored. Relative paths are relative to the manifest's
// folder. Ids must be unique and use only [A-Za-z0-9._+-] (not starting
// with "."). Errors: InputError naming the manifest and line.
//
// Every list returned is sorted by id (byte order): the order of the summary
// and the order shards partition.
#ifndef BESPOKE_PIPELINE_BATCH_SCAN_LIST_H_
#define BESPOKE_PIPELINE_BATCH_SCAN_LIST_H_

#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/batch/csv.h"  // manifests are CSV

namespace bespoke {

struct ScanEntry {
  std::string id;                   // folder name of the scan's outputs
  std::filesystem::path path;       // absolute, lexically normal
  std::string design;               // "" = the batch's --design
  std::string units;                // "" = the batch's --units (or guessed)
  std::filesystem::path landmarks;  // "" = none; a landmark override JSON
};

struct DiscoverOptions {
  bool recursive = false;  // descend into sub-folders (default: no)
  // A folder not to descend into (the batch's output folder when it lies
  // inside the input folder); empty = none.
  std::filesystem::path exclude;
};

// True for the scan extensions listed above (case-insensitive).
bool HasScanExtension(const std::filesystem::path& path);

// Scans in `dir`. InputError when `dir` is not a readable folder.
std::vector<ScanEntry> DiscoverScans(const DiscoverOptions& options,
                                     const std::filesystem::path& dir);

// Scans listed in a manifest CSV. InputError for a malformed manifest.
std::vector<ScanEntry> ReadManifest(const std::filesystem::path& manifest);

// A folder -> DiscoverScans, a file -> ReadManifest. InputError when `input`
// does not exist.
std::vector<ScanEntry> ListScans(const DiscoverOptions& options,
                                 const std::filesystem::path& input);

// Shard `index` of `count` (1-based: 1/4 .. 4/4).
struct Shard {
  int index = 1;
  int count = 1;
  bool whole() const { return count == 1; }
  std::string ToString() const;  // "2/4"
  std::string DirName() const;   // "shard-2-of-4"
};

// Parses "I/N" with 1 <= I <= N <= 100000; InputError otherwise.
Shard ParseShard(const std::string& text);

// The scans of `shard`: positions p (0-based, in the id-sorted list) with
// p % count == index - 1. Round robin keeps shard sizes within one of each
// other and does not depend on anything but the sorted list.
std::vector<ScanEntry> SelectShard(const std::vector<ScanEntry>& sorted_scans, const Shard& shard);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_SCAN_LIST_H_
