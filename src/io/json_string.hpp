#pragma once
// Text of any bytes as a JSON string. Names in a report come from files and the command
// line (a structure's name, an output path, mmCIF atom and residue names) and may hold any
// byte, while JSON (RFC 8259) must be UTF-8 with every control character escaped: each
// byte sequence that is not valid UTF-8 becomes U+FFFD (the replacement character, as
// WHATWG decoders do: one per maximal invalid subpart), control characters \u00XX (or
// \n \t \r \b \f), '"' and '\' their escapes; valid UTF-8 is kept as it is.
#include <string>
#include <string_view>

namespace molsurf::io {

// Appends `bytes` to `out` as a quoted JSON string.
void append_json_string(std::string& out, std::string_view bytes);

}  // namespace molsurf::io
