// Writing output files so that nothing half-written is ever left behind.
//
// The data goes to a temporary file beside the target ("<name>.tmp-<pid>-<n>"),
// is flushed and fsync'ed, and only then renamed over the target; rename()
// within one directory is atomic on POSIX file systems. If anything throws
// before Commit(), the temporary file is removed and the target is untouched.
//
//   AtomicFile out("report.json");        // throws InputError if the folder is missing
//   out.stream() << json.dump(2);
//   out.Commit();                         // target now has the complete content
#ifndef BESPOKE_SCANNERS_CORE_ATOMIC_FILE_H_
#define BESPOKE_SCANNERS_CORE_ATOMIC_FILE_H_

#include <filesystem>
#include <fstream>
#include <string_view>

namespace bespoke {

class AtomicFile {
 public:
  // Opens the temporary file (binary mode). Throws InputError when the target's
  // folder does not exist or is not writable.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();  // removes the temporary file unless committed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::filesystem::path& target() const { return target_; }

  // Flushes, fsyncs and renames onto the target. Throws InternalError when
  // the write failed (e.g. disk full); the target is then untouched.
  void Commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::ofstream out_;
  bool committed_ = false;
};

// Writes `contents` to `target` atomically.
void WriteFileAtomically(const std::filesystem::path& target, std::string_view contents);

// Creates `dir` and its parents if needed; throws InputError naming `dir` on failure.
void CreateDirectories(const std::filesystem::path& dir);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_ATOMIC_FILE_H_
