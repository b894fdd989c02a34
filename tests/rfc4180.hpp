#pragma once
// A strict RFC 4180 reader, written from the RFC for the tests: rows end at CRLF or LF
// outside quotes; a field is either plain (no quote, comma or line break) or enclosed in
// double quotes with each inner quote doubled. Malformed input throws, so a table that
// reads back proves that its writer quoted every field that needed it.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace molsurf::testing {

inline std::vector<std::vector<std::string>> read_rfc4180(std::string_view text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::size_t i = 0;
  while (i < text.size()) {
    std::string field;
    if (text[i] == '"') {
      ++i;
      while (true) {
        if (i >= text.size()) throw std::runtime_error("unterminated quoted field");
        if (text[i] == '"') {
          if (i + 1 < text.size() && text[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        field += text[i++];
      }
    } else {
      while (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
        if (text[i] == '"') throw std::runtime_error("quote inside an unquoted field");
        field += text[i++];
      }
    }
    row.push_back(std::move(field));
    if (i >= text.size()) throw std::runtime_error("last row without a line end");
    if (text[i] == ',') {
      ++i;
      continue;
    }
    if (text[i] == '\r') {
      if (i + 1 >= text.size() || text[i + 1] != '\n') throw std::runtime_error("CR without LF");
      ++i;
    }
    if (text[i] != '\n') throw std::runtime_error("text after a quoted field");
    ++i;
    rows.push_back(std::move(row));
    row.clear();
  }
  return rows;
}

}  // namespace molsurf::testing
