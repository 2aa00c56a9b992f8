// Progress reporting from long-running library code.
//
// Library functions that can run for more than a second take a `Progress*`
// (may be null: then nothing is reported). The CLI supplies one that draws a
// bar with rate and ETA on a terminal and stays quiet (or logs plain lines)
// in scripts; see pipeline/cli/progress_bar.h. Tests pass nullptr.
#ifndef BESPOKE_SCANNERS_CORE_PROGRESS_H_
#define BESPOKE_SCANNERS_CORE_PROGRESS_H_

#include <cstdint>
#include <string_view>

namespace bespoke {

class Progress {
 public:
  virtual ~Progress() = default;
  // A new stage of `total` steps begins ("cleaning", "propagating"); total 0
  // means unknown.
  virtual void Begin(std::string_view stage, std::int64_t total) = 0;
  // `done` steps of the current stage are finished. Cheap; may be called often.
  virtual void Update(std::int64_t done) = 0;
  // The current stage is finished.
  virtual void End() = 0;
};

// Null-safe helpers so callers need not test the pointer.
inline void ProgressBegin(Progress* p, std::string_view stage, std::int64_t total) {
  if (p) p->Begin(stage, total);
}
inline void ProgressUpdate(Progress* p, std::int64_t done) {
  if (p) p->Update(done);
}
inline void ProgressEnd(Progress* p) {
  if (p) p->End();
}

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_PROGRESS_H_
