#include "io/json_string.hpp"

#include <cstdio>

namespace molsurf::io {

namespace {

// What a lead byte announces (RFC 3629): the sequence's length (0: not a lead byte) and the
// range of its second byte, which excludes overlong forms, surrogates and code points
// beyond U+10FFFF; later bytes are 0x80..0xBF.
struct Lead {
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;
};

Lead lead_of(unsigned char c) {
  if (c >= 0xC2 && c <= 0xDF) return {2};
  if (c == 0xE0) return {3, 0xA0, 0xBF};
  if (c == 0xED) return {3, 0x80, 0x9F};
  if (c >= 0xE1 && c <= 0xEF) return {3};
  if (c == 0xF0) return {4, 0x90, 0xBF};
  if (c == 0xF4) return {4, 0x80, 0x8F};
  if (c >= 0xF1 && c <= 0xF3) return {4};
  return {};
}

// How many bytes from text[i] fit the sequence its lead byte starts: its whole length when
// it is valid, else the maximal subpart that one U+FFFD replaces (at least 1).
std::size_t fitting_bytes(std::string_view text, std::size_t i, const Lead& lead) {
  std::size_t k = 1;
  for (; k < lead.length && i + k < text.size(); ++k) {
    const unsigned char next = static_cast<unsigned char>(text[i + k]);
    const unsigned char low = k == 1 ? lead.low : 0x80, high = k == 1 ? lead.high : 0xBF;
    if (next < low || next > high) break;
  }
  return k;
}

}  // namespace

void append_json_string(std::string& out, std::string_view bytes) {
  out += '"';
  std::size_t i = 0;
  while (i < bytes.size()) {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c >= 0x80) {
      const Lead lead = lead_of(c);
      const std::size_t fitting = fitting_bytes(bytes, i, lead);
      if (lead.length != 0 && fitting == lead.length)
        out.append(bytes.substr(i, fitting));
      else
        out += "\xEF\xBF\xBD";  // U+FFFD
      i += fitting;
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (c < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
          out += escape;
        } else {
          out += static_cast<char>(c);
        }
    }
    ++i;
  }
  out += '"';
}

}  // namespace molsurf::io
