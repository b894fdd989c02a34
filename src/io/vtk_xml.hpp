#pragma once
// Internal: the elements of a VTK XML file (.vtp), parsed without trusting any size in it.
// Only what VTK writes is understood: elements, attributes, text, comments, declarations.
// Parsing stops at <AppendedData>, whose bytes after '_' are raw or base64 data.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace molsurf::mesh_io {

struct XmlElement {
  std::string_view name;
  std::vector<std::pair<std::string_view, std::string>> attributes;  // entities decoded
  std::size_t line = 0;        // 1-based line of the start tag
  // The text before the first child element, or all of it without children: VTK writes a
  // DataArray's values first, then InformationKey children.
  std::string_view text;
  std::vector<std::size_t> children;  // indices into XmlDocument::elements

  std::optional<std::string_view> attribute(std::string_view key) const;
};

struct XmlDocument {
  std::vector<XmlElement> elements;  // elements[0] is the root
  bool has_appended = false;
  std::string_view appended;         // the bytes after <AppendedData ...>'s '_'
  std::optional<std::string> appended_encoding;
};

// Throws molsurf::Error "FILE:LINE: problem" for anything that is not well-formed.
XmlDocument parse_vtk_xml(const std::filesystem::path& file, std::string_view bytes);

}  // namespace molsurf::mesh_io
