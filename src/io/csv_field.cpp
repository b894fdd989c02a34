#include "io/csv_field.hpp"

namespace molsurf::io {

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string field = "\"";
  for (const char c : text) {
    if (c == '"') field += '"';
    field += c;
  }
  field += '"';
  return field;
}

std::string prepend_csv_column(std::string_view csv, std::string_view name, std::string_view value,
                               bool with_header) {
  std::string out;
  bool quoted = false, row_start = true, in_header = true;
  for (const char c : csv) {
    const bool kept = !in_header || with_header;
    if (row_start && kept) (out += in_header ? name : value) += ',';
    row_start = false;
    if (c == '"') quoted = !quoted;  // a doubled quote toggles twice: still inside
    if (kept) out += c;
    if (c == '\n' && !quoted) row_start = true, in_header = false;
  }
  return out;
}

}  // namespace molsurf::io
