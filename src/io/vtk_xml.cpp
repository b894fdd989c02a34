// A small XML parser for VTK's XML files. VTK's own (expat underneath) is sound, but the
// reader on top of it trusts every size the file declares; reading the elements here lets
// the .vtp reader (mesh_vtp.cpp) check each size against the bytes present. The parse is
// iterative (no recursion on nesting depth) and stores views into the file's bytes.
#include "io/vtk_xml.hpp"

#include <algorithm>
#include <cctype>

#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

std::optional<std::string_view> XmlElement::attribute(std::string_view key) const {
  for (const auto& [name, value] : attributes)
    if (name == key) return std::string_view(value);
  return std::nullopt;
}

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':'; }
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '.' || c == '-';
}

// What a file holds, printable in a one-line message.
std::string shown(std::string_view text) {
  std::string out;
  for (const char c : text.substr(0, 24)) out += c >= 0x20 && c < 0x7f ? c : '?';
  return "'" + out + (text.size() > 24 ? "...'" : "'");
}

class Parser {
 public:
  Parser(const std::filesystem::path& file, std::string_view bytes) : file_(file), bytes_(bytes) {}

  XmlDocument run() {
    std::vector<std::size_t> open;  // indices of the elements not yet closed
    while (true) {
      const std::size_t lt = bytes_.find('<', position_);
      if (lt == std::string_view::npos) break;
      advance_to(lt);
      const std::string_view rest = bytes_.substr(position_);
      if (rest.starts_with("<?")) {
        skip_past("?>", "an unterminated <? ?> declaration");
      } else if (rest.starts_with("<!--")) {
        skip_past("-->", "an unterminated comment");
      } else if (rest.starts_with("<![CDATA[")) {
        fail(file_, line_, "CDATA sections are not part of a VTK file");
      } else if (rest.starts_with("<!")) {
        skip_past(">", "an unterminated <! > declaration");
      } else if (rest.starts_with("</")) {
        const std::size_t tag_line = line_;
        const std::size_t text_end = position_;
        advance_to(position_ + 2);
        const std::string_view name = read_name();
        skip_spaces();
        if (position_ >= bytes_.size() || bytes_[position_] != '>') fail(file_, tag_line, "malformed end tag </" + std::string(name));
        advance_to(position_ + 1);
        if (open.empty()) fail(file_, tag_line, "end tag </" + std::string(name) + "> without a start tag");
        XmlElement& element = document_.elements[open.back()];
        if (element.name != name)
          fail(file_, tag_line, "</" + std::string(name) + "> closes <" + std::string(element.name) + "> of line " +
                                    std::to_string(element.line));
        if (element.children.empty())
          element.text = bytes_.substr(text_start_[open.back()], text_end - text_start_[open.back()]);
        open.pop_back();
      } else {
        if (open.empty() && !document_.elements.empty())
          fail(file_, line_, "a second root element after </" + std::string(document_.elements[0].name) + ">");
        const std::size_t index = document_.elements.size(), tag_start = position_;
        const bool self_closing = read_start_tag();
        if (!open.empty()) {
          XmlElement& parent = document_.elements[open.back()];
          if (parent.children.empty())
            parent.text = bytes_.substr(text_start_[open.back()], tag_start - text_start_[open.back()]);
          parent.children.push_back(index);
        }
        if (document_.elements[index].name == "AppendedData" && !self_closing) {
          read_appended(index);
          return std::move(document_);
        }
        if (!self_closing) open.push_back(index);
      }
    }
    if (document_.elements.empty()) fail(file_, "not an XML file (no element)");
    if (!open.empty())
      fail(file_, line_, "truncated: <" + std::string(document_.elements[open.back()].name) + "> of line " +
                             std::to_string(document_.elements[open.back()].line) + " is not closed");
    return std::move(document_);
  }

 private:
  void advance_to(std::size_t target) {
    line_ += static_cast<std::size_t>(std::count(bytes_.begin() + static_cast<std::ptrdiff_t>(position_),
                                                 bytes_.begin() + static_cast<std::ptrdiff_t>(target), '\n'));
    position_ = target;
  }
  void skip_past(std::string_view end, const char* what) {
    const std::size_t found = bytes_.find(end, position_);
    if (found == std::string_view::npos) fail(file_, line_, std::string("truncated: ") + what);
    advance_to(found + end.size());
  }
  void skip_spaces() {
    std::size_t p = position_;
    while (p < bytes_.size() && is_space(bytes_[p])) ++p;
    advance_to(p);
  }
  std::string_view read_name() {
    const std::size_t start = position_;
    if (position_ >= bytes_.size() || !is_name_start(bytes_[position_]))
      fail(file_, line_, "malformed XML: expected a name, found " + shown(bytes_.substr(position_)));
    std::size_t p = position_;
    while (p < bytes_.size() && is_name_char(bytes_[p])) ++p;
    advance_to(p);
    return bytes_.substr(start, p - start);
  }

  // Reads "<name a="v" ...>" or ".../>" at position_; returns whether it closes itself.
  bool read_start_tag() {
    XmlElement element;
    element.line = line_;
    advance_to(position_ + 1);
    element.name = read_name();
    while (true) {
      skip_spaces();
      if (position_ >= bytes_.size())
        fail(file_, element.line, "truncated: <" + std::string(element.name) + " tag is not closed");
      if (bytes_[position_] == '>' || bytes_.substr(position_).starts_with("/>")) break;
      const std::string_view key = read_name();
      skip_spaces();
      if (position_ >= bytes_.size() || bytes_[position_] != '=')
        fail(file_, line_, "malformed attribute " + shown(key) + " of <" + std::string(element.name) + ">");
      advance_to(position_ + 1);
      skip_spaces();
      const char quote = position_ < bytes_.size() ? bytes_[position_] : '\0';
      const std::size_t end = quote == '"' || quote == '\'' ? bytes_.find(quote, position_ + 1) : std::string_view::npos;
      if (end == std::string_view::npos)
        fail(file_, line_, "malformed attribute " + shown(key) + " of <" + std::string(element.name) + ">");
      const std::string_view raw = bytes_.substr(position_ + 1, end - position_ - 1);
      if (raw.find('<') != std::string_view::npos)
        fail(file_, line_, "'<' in attribute " + shown(key) + " of <" + std::string(element.name) + ">");
      for (const auto& [name, value] : element.attributes)
        if (name == key) fail(file_, line_, "attribute " + shown(key) + " given twice");
      element.attributes.emplace_back(key, decode_entities(raw));
      advance_to(end + 1);
    }
    const bool self_closing = bytes_[position_] == '/';
    advance_to(position_ + (self_closing ? 2 : 1));
    document_.elements.push_back(std::move(element));
    text_start_.push_back(position_);
    return self_closing;
  }

  // The five predefined entities and character references below 128; others stay as written.
  static std::string decode_entities(std::string_view raw) {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      static constexpr std::pair<std::string_view, char> kEntities[] = {
          {"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'}, {"&apos;", '\''}};
      bool done = false;
      for (const auto& [entity, c] : kEntities)
        if (raw.substr(i).starts_with(entity)) {
          out += c;
          i += entity.size() - 1;
          done = true;
          break;
        }
      if (!done) out += '&';
    }
    return out;
  }

  // Raw data follows '_' (with only blanks between '>' and '_'), up to </AppendedData>.
  void read_appended(std::size_t index) {
    const XmlElement& element = document_.elements[index];
    skip_spaces();
    if (position_ >= bytes_.size() || bytes_[position_] != '_')
      fail(file_, element.line, "<AppendedData>: expected '_' before the data");
    const std::size_t start = position_ + 1;
    const std::size_t end = bytes_.rfind("</AppendedData>");
    document_.has_appended = true;
    document_.appended = bytes_.substr(start, end == std::string_view::npos || end < start ? std::string_view::npos : end - start);
    if (const auto encoding = element.attribute("encoding")) document_.appended_encoding = std::string(*encoding);
  }

  const std::filesystem::path& file_;
  std::string_view bytes_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;
  XmlDocument document_;
  std::vector<std::size_t> text_start_;  // per element: where its text begins
};

}  // namespace

XmlDocument parse_vtk_xml(const std::filesystem::path& file, std::string_view bytes) { return Parser(file, bytes).run(); }

}  // namespace molsurf::mesh_io
