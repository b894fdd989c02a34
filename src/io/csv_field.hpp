#pragma once
// CSV as RFC 4180 writes it. The tables' names come from the structure file, and mmCIF
// allows any text in a name (a comma, a quote, a line break in a quoted or
// semicolon-delimited value): such a field is enclosed in double quotes with each quote
// doubled, so that every CSV reader gets the same rows and columns back.
#include <string>
#include <string_view>

namespace molsurf::io {

// `text` as one CSV field: as it is when it holds no comma, quote, CR or LF, else quoted.
std::string csv_field(std::string_view text);

// `csv` with a column `name` in front (the header row, when `with_header`) and `value` in
// front of every data row. Rows end at line breaks outside quoted fields.
std::string prepend_csv_column(std::string_view csv, std::string_view name, std::string_view value,
                               bool with_header);

}  // namespace molsurf::io
