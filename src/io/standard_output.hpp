#pragma once
// Reports written to standard output are outputs like files: a write that fails (a full
// disk, /dev/full, a closed descriptor) is an error, never a lost report and exit 0.
#include <string_view>

namespace molsurf {

// Gives each of the descriptors 0, 1 and 2 that is closed (`molsurf ... >&-`) a read-only
// /dev/null, so that no file opened later takes its number (a report printed to standard
// output would land in it) and every write to it fails, as a write to a closed descriptor
// must. Also gives standard output (unless a terminal) a buffer larger than any text report,
// so that text is written where a caller flushes it. For programs: call it first thing in
// main(), before anything is printed.
void guard_standard_streams() noexcept;

// Writes `text` to standard output and flushes it; throws molsurf::Error
// ("standard output: cannot write: REASON") when any of it cannot be written.
void write_standard_output(std::string_view text);

// Flushes std::cout and stdout; throws molsurf::Error as above when anything written to
// them since the start failed (with the system's reason when this flush is the one that
// failed: flush where text must be out, before files replace their targets).
void flush_standard_output();

}  // namespace molsurf
