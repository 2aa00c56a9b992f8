// libFuzzer target: the OFF reader (and format detection, units, non-finite
// points) on arbitrary bytes. Built with -DBESPOKE_FUZZ=ON; run scripts/fuzz.sh.
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bespoke::fuzz::ReadEverything(data, size, "fuzz.off");
  return 0;
}
