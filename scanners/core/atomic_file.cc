#include "scanners/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

std::filesystem::path TempPathFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() / (target.filename().string() + ".tmp-" + std::to_string(::getpid()) +
                                 "-" + std::to_string(counter++));
}

void FsyncPath(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return;  // best effort: some file systems refuse directories
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  std::filesystem::path dir = target_.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(target_, "cannot write: folder '" + dir.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(target_, ec)) {
    throw InputError(target_, "cannot write: a folder of that name exists");
  }
  temp_ = TempPathFor(target_);
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    throw InputError(target_, std::string("cannot write: ") + std::strerror(errno));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
}

void AtomicFile::Commit() {
  BESPOKE_CHECK(!committed_, "AtomicFile committed twice");
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) {
    throw InternalError("writing " + target_.string() + " failed (disk full?)");
  }
  FsyncPath(temp_, O_RDONLY);
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    throw InternalError("cannot rename " + temp_.string() + " to " + target_.string() + ": " +
                        std::strerror(errno));
  }
  committed_ = true;
  std::filesystem::path dir = target_.parent_path();
  FsyncPath(dir.empty() ? "." : dir, O_RDONLY | O_DIRECTORY);
}

void WriteFileAtomically(const std::filesystem::path& target, std::string_view contents) {
  AtomicFile file(target);
  file.stream().write(contents.data(), static_cast<std::streamsize>(contents.size()));
  file.Commit();
}

void CreateDirectories(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir, "cannot create folder: " + (ec ? ec.message() : "not a folder"));
  }
}

}  // namespace bespoke
