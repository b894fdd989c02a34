#include "blocks/pvtp_index.hpp"

namespace molsurf::blocks {

namespace {

// XML attribute text: the piece names are the user's file names.
std::string xml_attribute(const std::string& text) {
  std::string out;
  for (char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  return out;
}

}  // namespace

std::filesystem::path piece_path(const std::filesystem::path& index, std::size_t block) {
  std::filesystem::path piece = index;
  piece.replace_filename(index.stem().string() + "_" + std::to_string(block) + ".vtp");
  return piece;
}

std::filesystem::path seams_path(const std::filesystem::path& index) {
  std::filesystem::path seams = index;
  seams.replace_filename(index.stem().string() + "_seams.vtp");
  return seams;
}

std::string pvtp_index(const std::filesystem::path& index, std::size_t pieces, bool with_seams) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <PPolyData GhostLevel=\"0\">\n"
      "    <PPointData Normals=\"Normals\">\n"
      "      <PDataArray type=\"Float32\" Name=\"Normals\" NumberOfComponents=\"3\"/>\n"
      "    </PPointData>\n"
      "    <PCellData>\n"
      "      <PDataArray type=\"Int32\" Name=\"tag\"/>\n"
      "      <PDataArray type=\"Int32\" Name=\"atom_serial\"/>\n"
      "      <PDataArray type=\"Int32\" Name=\"residue_number\"/>\n"
      "      <PDataArray type=\"String\" Name=\"residue_name\"/>\n"
      "      <PDataArray type=\"String\" Name=\"chain\"/>\n"
      "    </PCellData>\n"
      "    <PPoints>\n"
      "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
      "    </PPoints>\n";
  for (std::size_t k = 0; k < pieces; ++k)
    xml += "    <Piece Source=\"" + xml_attribute(piece_path(index, k).filename().string()) + "\"/>\n";
  if (with_seams) xml += "    <Piece Source=\"" + xml_attribute(seams_path(index).filename().string()) + "\"/>\n";
  xml += "  </PPolyData>\n</VTKFile>\n";
  return xml;
}

}  // namespace molsurf::blocks
