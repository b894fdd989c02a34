#pragma once
// Below this many items a loop runs on the calling thread: starting an OpenMP team and
// meeting at its barrier costs more than the loop (about 50 ms per region on a loaded
// machine, where idle workers spin), and many small meshes are checked one after another
// (one per component with --split-components).
#include <cstdint>

namespace molsurf {

inline constexpr std::int64_t kParallelMinItems = 16384;

}  // namespace molsurf
