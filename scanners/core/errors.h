// Typed errors thrown by every Bespoke library.
//
// Library code never aborts and never calls exit(): it throws one of these.
// Only `main` (pipeline/cli/main.cc) turns them into process exit codes:
//   InputError    -> exit 1  (the user's file, option or data is wrong)
//   InternalError -> exit 2  (a bug or an unexpected failure inside Bespoke)
// Any other std::exception reaching main is treated as an InternalError.
//
// Messages name the file (when there is one) and say what is wrong in words a
// user can act on, e.g.
//   "scan.ply: header declares 5000000000 vertices but the file has 1204 bytes of data".
#ifndef BESPOKE_SCANNERS_CORE_ERRORS_H_
#define BESPOKE_SCANNERS_CORE_ERRORS_H_

#include <filesystem>
#include <stdexcept>
#include <string>

namespace bespoke {

// Base of all Bespoke errors.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input: malformed or truncated file, unknown option value, a scan with
// too few points, a pattern whose outline self-intersects. Exit code 1.
class InputError : public Error {
 public:
  using Error::Error;
  // "<path>: <what>"
  InputError(const std::filesystem::path& file, const std::string& what)
      : Error(file.string() + ": " + what) {}
};

// Something that should not happen did: a solver diverged, an invariant broke,
// a file could not be written. Exit code 2.
class InternalError : public Error {
 public:
  using Error::Error;
};

// Throws InternalError("<what> (<file>:<line>)") when `condition` is false.
// For invariants of Bespoke's own code, not for checking user input.
#define BESPOKE_CHECK(condition, what)                                           \
  do {                                                                           \
    if (!(condition))                                                            \
      throw ::bespoke::InternalError(std::string(what) + " (" + __FILE__ + ":" + \
                                     std::to_string(__LINE__) + ")");            \
  } while (false)

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_ERRORS_H_
