// Property: whatever damage a mesh file takes (truncation, flipped bytes, digits turned
// into huge or negative numbers), reading it gives a molsurf::Error naming the file, or a
// mesh whose indices are in range and which check_mesh() can judge. Never a crash, never
// another exception. Every format, VTK's included; fixed seeds, so failures repeat.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "mesh/icosphere.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

namespace fs = std::filesystem;
using namespace molsurf;

namespace {

class MeshReadProperty : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "molsurf_read_property_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static void put(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

  // Reads `file` (and for MSMS its pair) and checks the property; `what` names the case.
  static void expect_error_or_mesh(const fs::path& file, const std::string& what) {
    try {
      const Mesh mesh = read_mesh(file);
      for (const Triangle& t : mesh.faces)
        for (Index v : t) ASSERT_LT(v, mesh.vertex_count()) << what;
      if (mesh.face_count() <= 2000) {
        const MeshCheck check = check_mesh(mesh);
        EXPECT_EQ(check.valid(), check.defects().empty()) << what;
      }
    } catch (const Error& error) {
      const std::string message = error.what();
      // "FILE: problem" or "FILE:LINE: problem"; MSMS errors may name the other file of the pair.
      EXPECT_EQ(message.rfind((file.parent_path() / file.stem()).string(), 0), 0u) << what << ": " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << what << ": one line: " << message;
    } catch (const std::exception& error) {
      ADD_FAILURE() << what << ": " << typeid(error).name() << ": " << error.what();
    }
  }

  fs::path dir_;
};

// MSMS is a pair: the damage goes to one file of it, the other stays whole.
TEST_P(MeshReadProperty, DamageGivesAnErrorOrAMesh) {
  const std::string name = std::string("m") + GetParam();
  const bool msms = name.ends_with(".vert");
  Mesh mesh = make_icosphere({0.25, -1.5, 3.0}, 1.7, {.frequency = 2, .tag = 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) mesh.face_tags[f] = static_cast<std::int32_t>(f % 5);
  std::mt19937 random(20240611);
  for (const bool ascii : {false, true}) {
    write_mesh(dir_ / name, mesh, {.ascii = ascii});
    for (const fs::path target : {dir_ / name, dir_ / "m.face"}) {
      if (target.extension() == ".face" && !msms) continue;
      const std::string bytes = slurp(target);
      const std::string pair_copy = msms ? slurp(target == dir_ / name ? dir_ / "m.face" : dir_ / name) : "";
      const auto run = [&](const std::string& damaged, const std::string& what) {
        put(target, damaged);
        expect_error_or_mesh(dir_ / name, name + (ascii ? " ascii " : " ") + target.filename().string() + ": " + what);
        put(target, bytes);
      };
      // Truncation at 60 places, including inside every header.
      for (int k = 0; k <= 60; ++k) run(bytes.substr(0, bytes.size() * k / 60), "cut at " + std::to_string(k) + "/60");
      for (int trial = 0; trial < 120; ++trial) {
        std::string copy = bytes;
        const int kind = trial % 3;
        if (kind == 0) {  // a few random bytes
          for (int h = 1 + static_cast<int>(random() % 4); h > 0; --h)
            copy[random() % copy.size()] = static_cast<char>(random() % 256);
        } else {  // a digit becomes a huge or negative number: the header bombs
          const std::size_t at = copy.find_first_of("0123456789", random() % copy.size());
          if (at == std::string::npos) continue;
          copy.replace(at, 1, kind == 1 ? "2000000000" : "-12");
        }
        run(copy, "trial " + std::to_string(trial));
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, MeshReadProperty,
                         ::testing::Values(".vtp", ".vtk", ".ply", ".off", ".stl", ".obj", ".vert", ".msh"),
                         [](const auto& info) { return std::string(info.param).substr(1); });

}  // namespace
