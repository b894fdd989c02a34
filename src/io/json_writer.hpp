#pragma once
// A minimal streaming JSON writer for reports: objects, arrays, strings (any bytes, as
// json_string.hpp escapes them), numbers, booleans.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <type_traits>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_string.hpp"

namespace molsurf::io {

class JsonWriter {
 public:
  JsonWriter& begin_object() { open('{'); return *this; }
  JsonWriter& end_object() { close('}'); return *this; }
  JsonWriter& begin_array() { open('['); return *this; }
  JsonWriter& end_array() { close(']'); return *this; }

  JsonWriter& key(std::string_view name) {
    separate();
    write_string(name);
    out_ += ": ";
    after_key_ = true;
    return *this;
  }
  JsonWriter& value(std::string_view s) { separate(); write_string(s); return *this; }
  JsonWriter& value(const char* s) { return value(std::string_view(s)); }
  JsonWriter& value(bool b) { separate(); out_ += b ? "true" : "false"; return *this; }
  JsonWriter& null() { separate(); out_ += "null"; return *this; }
  JsonWriter& value(double d) {
    separate();
    if (!std::isfinite(d)) { out_ += "null"; return *this; }
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
    out_.append(buf, end);
    return *this;
  }
  template <typename Int>
    requires std::is_integral_v<Int> && (!std::is_same_v<Int, bool>)
  JsonWriter& value(Int i) { separate(); out_ += std::to_string(i); return *this; }

  template <typename T>
  JsonWriter& field(std::string_view name, const T& v) { key(name); return value(v); }

  std::string str() const { return out_ + "\n"; }

 private:
  void open(char c) {
    separate();
    out_ += c;
    first_.push_back(true);
  }
  void close(char c) {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty) newline();
    out_ += c;
  }
  void separate() {
    if (after_key_) { after_key_ = false; return; }
    if (first_.empty()) return;
    if (!first_.back()) out_ += ',';
    first_.back() = false;
    newline();
  }
  void newline() {
    out_ += '\n';
    out_.append(2 * first_.size(), ' ');
  }
  void write_string(std::string_view s) { append_json_string(out_, s); }

  std::string out_;
  std::vector<bool> first_;
  bool after_key_ = false;
};

}  // namespace molsurf::io
