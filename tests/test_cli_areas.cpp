// The command line's exact areas: --areas-only (no mesh, nothing written unless asked) and
// the true spheres' numbers in the mesh's report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <numeric>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "molsurf/atoms.hpp"

namespace molsurf {
namespace {

using testing::json_number;
using testing::read_text;
using testing::run_molsurf;
using testing::TempDir;

const std::string kData = MOLSURF_DATA_DIR;

// The last column of each data row of a CSV file.
std::vector<double> last_column(const std::string& csv) {
  std::vector<double> values;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) values.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  return values;
}

TEST(CliAreas, AreasOnlyWritesNoMeshAndReportsWhatItWasAskedFor) {
  TempDir dir;
  const auto r = run_molsurf("--areas-only --json r.json --per-atom a.csv '" + kData + "/pdb/1crn.pdb'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"a.csv", "r.json"}));  // no 1crn.vtp
  EXPECT_NE(r.out.find("true spheres"), std::string::npos) << r.out;
  const std::string json = read_text(dir.path() / "r.json");
  EXPECT_NE(json.find("\"areas_only\": true"), std::string::npos);
  const double area = json_number(json, "area");
  // Exact union of balls (docs/accuracy.md: 3001.47 A^2 by 4000 slices per ball).
  EXPECT_NEAR(area, 3001.47, 0.01);
  // The CSV prints each atom's area to the last bit: its sum is the total to rounding.
  double sum = 0;
  for (double a : last_column(read_text(dir.path() / "a.csv"))) sum += a;
  EXPECT_NEAR(sum, area, 1e-10 * area);
}

TEST(CliAreas, MeshReportGivesTheTrueSpheresAndTheFacets) {
  TempDir dir;
  const auto mesh = run_molsurf("-q --json mesh.json -o s.vtp '" + kData + "/pdb/1crn.pdb'", dir.path());
  const auto only = run_molsurf("-q --areas-only --json only.json '" + kData + "/pdb/1crn.pdb'", dir.path());
  ASSERT_EQ(mesh.exit_code, 0) << mesh.err;
  ASSERT_EQ(only.exit_code, 0) << only.err;
  const std::string m = read_text(dir.path() / "mesh.json"), o = read_text(dir.path() / "only.json");
  // The same arrangement: the same numbers to the last bit.
  EXPECT_EQ(json_number(m, "area"), json_number(o, "area"));
  EXPECT_EQ(json_number(m, "volume"), json_number(o, "volume"));
  // The facets' own area is there too, within the faceting's half a percent.
  const double facets = json_number(m, "facet_area"), exact = json_number(m, "area");
  EXPECT_NE(facets, exact);
  EXPECT_NEAR(facets, exact, 0.005 * exact);
}

TEST(CliAreas, AreasOnlyRefusesMeshOptionsBeforeAnyWork) {
  TempDir dir;
  for (const std::string& option : {"-o s.vtp", "--split-components", "--volume-mesh v.msh"}) {
    const auto r = run_molsurf("--areas-only " + option + " '" + kData + "/pdb/1crn.pdb'", dir.path());
    EXPECT_EQ(r.exit_code, 1) << option;
    EXPECT_NE(r.err.find("--areas-only"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << option;
  }
}

TEST(CliAreas, CavityWithCentroidAndLiningAtoms) {
  TempDir dir;
  {
    // Six spheres on the axes around an empty centre (test_sphere_arrangement_reference.cpp).
    std::ofstream xyzr(dir.path() / "six.xyzr");
    for (const char* line : {"2 0 0 1.75", "-2 0 0 1.75", "0 2 0 1.75", "0 -2 0 1.75", "0 0 2 1.75", "0 0 -2 1.75"})
      xyzr << line << "\n";
  }
  const auto r = run_molsurf("--areas-only --probe 0 --json r.json six.xyzr", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = read_text(dir.path() / "r.json");
  EXPECT_EQ(json_number(json, "cavities"), 1);
  const std::size_t cavity = json.find("\"kind\": \"cavity\"");
  ASSERT_NE(cavity, std::string::npos) << json;
  const std::string rest = json.substr(cavity);
  EXPECT_NEAR(json_number(rest, "area"), 1.911806, 1e-5);  // closed form (reference test)
  EXPECT_NEAR(json_number(rest, "volume"), 0.147862, 1e-5);
  const std::size_t atoms = rest.find("\"atoms\": [");
  ASSERT_NE(atoms, std::string::npos) << rest;
  std::string list = rest.substr(atoms + 10, rest.find(']', atoms) - atoms - 10);
  std::erase_if(list, [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
  EXPECT_EQ(list, "0,1,2,3,4,5");
}

TEST(CliAreas, PerChainAndRelativeSasa) {
  TempDir dir;
  const auto r = run_molsurf("-q --areas-only --per-chain chains.csv --per-residue res.csv --relative --json r.json '" +
                                 kData + "/pdb/2hhb.pdb'",
                             dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = read_text(dir.path() / "r.json");
  const double area = json_number(json, "area");
  double chains = 0;
  for (double a : last_column(read_text(dir.path() / "chains.csv"))) chains += a;
  EXPECT_NEAR(chains, area, 1e-10 * area);
  EXPECT_NE(json.find("\"chains\""), std::string::npos);
  EXPECT_NE(json.find("\"relative\""), std::string::npos);
  // Every amino acid's relative area is its area over Tien's theoretical maximum; the haem
  // groups have none.
  std::istringstream rows(read_text(dir.path() / "res.csv"));
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "chain,residue_name,residue_number,insertion_code,atoms,area,relative");
  int amino = 0, other = 0;
  while (std::getline(rows, line)) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    if (line.back() == ',') f.push_back("");
    ASSERT_EQ(f.size(), 7u) << line;
    if (f[1] == "HEM" || f[1] == "PO4") {
      EXPECT_EQ(f[6], "") << line;
      ++other;
    } else {
      ASSERT_FALSE(f[6].empty()) << line;
      const double max = f[1] == "ALA" ? 129 : f[1] == "GLY" ? 104 : 0;
      if (max > 0) EXPECT_NEAR(std::stod(f[6]), std::stod(f[5]) / max, 1e-12) << line;
      ++amino;
    }
  }
  EXPECT_EQ(amino, 574);
  EXPECT_GT(other, 0);
  const auto empirical = run_molsurf("-q --areas-only --per-residue - --relative --relative-scale empirical '" + kData +
                                         "/pdb/2hhb.pdb'",
                                     dir.path());
  ASSERT_EQ(empirical.exit_code, 0) << empirical.err;
  EXPECT_NE(empirical.out, read_text(dir.path() / "res.csv"));
}

TEST(CliAreas, SasaStructureCarriesEachAtomsAreaInItsBFactor) {
  TempDir dir;
  const auto r = run_molsurf("-q --areas-only --per-atom a.csv --sasa-structure s.pdb '" + kData + "/pdb/1crn.pdb'",
                             dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto c = run_molsurf("-q --areas-only --sasa-structure s.cif '" + kData + "/pdb/1crn.pdb'", dir.path());
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const std::vector<double> area = last_column(read_text(dir.path() / "a.csv"));
  const Structure original = read_structure(kData + "/pdb/1crn.pdb");
  // PDB's B-factor column holds two decimals; mmCIF's more.
  for (const auto& [file, tolerance] : {std::pair<std::string, double>{"s.pdb", 0.005}, {"s.cif", 1e-4}}) {
    const Structure s = read_structure(dir.path() / file);
    ASSERT_EQ(s.atoms.size(), area.size()) << file;
    for (std::size_t i = 0; i < area.size(); ++i) {
      EXPECT_NEAR(s.atoms[i].b_factor, area[i], tolerance * std::max(1.0, area[i])) << file << " atom " << i;
      EXPECT_NEAR(s.atoms[i].occupancy, original.atoms[i].radius, 1e-6) << file << " atom " << i;
      EXPECT_EQ(s.atoms[i].atom_name, original.atoms[i].atom_name);
      EXPECT_NEAR(s.atoms[i].centre.x, original.atoms[i].centre.x, 1e-3);
    }
  }
  const auto bad = run_molsurf("--areas-only --sasa-structure s.txt '" + kData + "/pdb/1crn.pdb'", dir.path());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--sasa-structure"), std::string::npos) << bad.err;
}

TEST(CliAreas, AllModelsOfAnNmrEnsembleInOneCall) {
  TempDir dir;
  const std::string file = "'" + kData + "/pdb/1j8k.cif'";
  const auto r = run_molsurf("-q --areas-only --all-models --json all.json --per-chain chains.csv " + file, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = read_text(dir.path() / "all.json");
  const std::size_t models = json.find("\"models\"");
  ASSERT_NE(models, std::string::npos);
  std::size_t count = 0;
  for (std::size_t at = json.find("\"model\": ", models); at != std::string::npos; at = json.find("\"model\": ", at + 1))
    ++count;
  EXPECT_EQ(count, 20u);
  // Each model's numbers are those of a run on that model alone, to the last bit.
  for (const int model : {1, 7, 20}) {
    const auto one = run_molsurf("-q --areas-only --model " + std::to_string(model) + " --json one.json " + file,
                                 dir.path());
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const double area = json_number(read_text(dir.path() / "one.json"), "area");
    const std::size_t entry = json.find("\"model\": " + std::to_string(model) + ",", models);
    ASSERT_NE(entry, std::string::npos) << model;
    EXPECT_EQ(json_number(json.substr(entry), "area"), area) << model;
  }
  const std::string chains = read_text(dir.path() / "chains.csv");
  EXPECT_EQ(chains.substr(0, chains.find('\n')), "model,chain,atoms,residues,area");
  EXPECT_EQ(std::count(chains.begin(), chains.end(), '\n'), 21);  // a header and one chain per model
}

// A two-model PDB file: 1crn, and 1crn with its first residue's atoms moved by 0.5 A.
std::filesystem::path two_model_file(const std::filesystem::path& dir) {
  std::ifstream in(kData + "/pdb/1crn.pdb");
  std::vector<std::string> atoms;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("ATOM", 0) == 0) atoms.push_back(line);
  const std::filesystem::path path = dir / "two.pdb";
  std::ofstream out(path);
  for (int model = 1; model <= 2; ++model) {
    out << "MODEL     " << std::setw(4) << model << "\n";
    for (std::string line : atoms) {
      if (model == 2 && line.substr(22, 4) == "   1") {
        char x[9];
        std::snprintf(x, sizeof x, "%8.3f", std::stod(line.substr(30, 8)) + 0.5);
        line.replace(30, 8, x);
      }
      out << line << "\n";
    }
    out << "ENDMDL\n";
  }
  out << "END\n";
  return path;
}

// --all-models writes meshes only when -o names them through {model}: one valid file per
// model, each model's numbers those of a run on it alone; without -o, numbers only.
TEST(CliAreas, AllModelsWritesOneMeshPerModelThroughTheNameTemplate) {
  TempDir dir;
  const std::string file = "'" + two_model_file(dir.path()).string() + "'";
  const auto r = run_molsurf("-q --all-models -o 's_{model}.off' --json all.json " + file, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = read_text(dir.path() / "all.json");
  const std::size_t models = json.find("\"models\"");
  ASSERT_NE(models, std::string::npos) << json;
  std::vector<double> areas;
  for (const int model : {1, 2}) {
    const std::string mesh = "s_" + std::to_string(model) + ".off";
    ASSERT_TRUE(std::filesystem::exists(dir.path() / mesh)) << mesh;
    const auto check = run_molsurf("check " + mesh, dir.path());
    EXPECT_EQ(check.exit_code, 0) << mesh << "\n" << check.out << check.err;
    const std::size_t entry = json.find("\"model\": " + std::to_string(model) + ",", models);
    ASSERT_NE(entry, std::string::npos) << model;
    const std::string entry_json = json.substr(entry, json.find('}', entry) - entry);
    EXPECT_NE(entry_json.find("\"output\": \"" + mesh + "\""), std::string::npos) << entry_json;
    EXPECT_GT(json_number(entry_json, "faces"), 1000);
    const auto one = run_molsurf("-q --areas-only --model " + std::to_string(model) + " --json one.json " + file,
                                 dir.path());
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(json_number(json.substr(entry), "area"), json_number(read_text(dir.path() / "one.json"), "area"));
    areas.push_back(json_number(json.substr(entry), "area"));
  }
  EXPECT_NE(areas[0], areas[1]);  // the models differ, and so do their numbers

  // Without {model} the files would overwrite each other: refused before any work.
  const auto same = run_molsurf("--all-models -o s.vtp " + file, dir.path());
  EXPECT_EQ(same.exit_code, 1);
  EXPECT_NE(same.err.find("{model}"), std::string::npos) << same.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.vtp"));
  // Without -o: the numbers, and no mesh anywhere.
  const auto numbers = run_molsurf("-q --all-models --json n.json " + file, dir.path());
  ASSERT_EQ(numbers.exit_code, 0) << numbers.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "two.vtp"));
  EXPECT_NE(read_text(dir.path() / "n.json").find("\"models\""), std::string::npos);
}

// Crambin's per-atom SES areas: every table and report gives each atom's share of the SES's
// patches (exact, the JSON's ses_patches), the facets' only in the facet totals; with
// --outer-only the outer surface's patches. Per residue and chain the same sums.
TEST(CliAreas, SesPerAtomResidueAndChainAreasAreItsPatches) {
  TempDir dir;
  const std::string file = "'" + kData + "/pdb/1crn.pdb'";
  const auto r = run_molsurf("-q --surface ses -o s.vtp --per-atom a.csv --per-residue r.csv --per-chain c.csv "
                             "--sasa-structure s.cif --json r.json --depth atom " + file,
                             dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(read_text(dir.path() / "r.json"));
  const double patches = report.at("ses_patches").at("area").get<double>();
  const double facets = report.at("facet_area").get<double>();
  // The report's area and volume are the patches', as the SAS's are its true spheres'.
  EXPECT_EQ(report.at("area").get<double>(), patches);
  EXPECT_EQ(report.at("volume").get<double>(), report.at("ses_patches").at("volume").get<double>());
  const std::vector<double> atoms = last_column(read_text(dir.path() / "a.csv"));
  ASSERT_EQ(atoms.size(), 327u);
  const auto sum = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); };
  EXPECT_NEAR(sum(atoms), patches, 1e-9 * patches);
  EXPECT_NEAR(sum(last_column(read_text(dir.path() / "r.csv"))), patches, 1e-9 * patches);
  EXPECT_NEAR(sum(last_column(read_text(dir.path() / "c.csv"))), patches, 1e-9 * patches);
  // The facets' total differs (the mesh is +0.42 % at density 2), within a percent.
  EXPECT_GT(std::abs(facets - patches), 1e-6 * patches);
  EXPECT_NEAR(facets, patches, 0.01 * patches);
  // The report's rows and the JSON's atoms: the same areas.
  const nlohmann::json& classes = report.at("classes");
  EXPECT_NEAR(classes.at("polar").get<double>() + classes.at("apolar").get<double>(), patches, 1e-9 * patches);
  EXPECT_NEAR(classes.at("main_chain").get<double>() + classes.at("side_chain").get<double>(), patches,
              1e-9 * patches);
  ASSERT_EQ(report.at("chains").size(), 1u);
  EXPECT_NEAR(report.at("chains")[0].at("area").get<double>(), patches, 1e-9 * patches);
  ASSERT_EQ(report.at("atoms").size(), atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i)
    EXPECT_EQ(report.at("atoms")[i].at("area").get<double>(), atoms[i]) << "atom " << i;
  const Structure written = read_structure(dir.path() / "s.cif");
  ASSERT_EQ(written.atoms.size(), atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i)
    EXPECT_NEAR(written.atoms[i].b_factor, atoms[i], 1e-4 * std::max(1.0, atoms[i])) << "atom " << i;

  // --outer-only: the outer surface's patches, less than the whole (crambin's SES has a cavity).
  const auto outer = run_molsurf("-q --surface ses --outer-only -o o.vtp --per-atom o.csv --per-chain oc.csv "
                                 "--json o.json " + file,
                                 dir.path());
  ASSERT_EQ(outer.exit_code, 0) << outer.err;
  const double outer_patches =
      nlohmann::json::parse(read_text(dir.path() / "o.json")).at("ses_patches").at("area").get<double>();
  EXPECT_LT(outer_patches, patches - 1);
  EXPECT_NEAR(sum(last_column(read_text(dir.path() / "o.csv"))), outer_patches, 1e-9 * outer_patches);
  EXPECT_NEAR(sum(last_column(read_text(dir.path() / "oc.csv"))), outer_patches, 1e-9 * outer_patches);

  // --all-models: each model's rows the same patches' areas.
  const auto models = run_molsurf(
      "-q --surface ses --all-models -o 'm_{model}.vtp' --per-atom m.csv --json m.json " + file, dir.path());
  ASSERT_EQ(models.exit_code, 0) << models.err;
  EXPECT_EQ(last_column(read_text(dir.path() / "m.csv")), atoms);
  const nlohmann::json model_rows = nlohmann::json::parse(read_text(dir.path() / "m.json")).at("models");
  ASSERT_EQ(model_rows.size(), 1u);
  EXPECT_EQ(model_rows[0].at("area").get<double>(), patches);
}

// FreeSASA's spellings: --radii names a built-in set, --config-file reads a FreeSASA
// configuration whose classes decide the polar and apolar areas.
TEST(CliAreas, FreeSasaRadiusNamesAndConfigurationFiles) {
  TempDir dir;
  const std::string file = "'" + kData + "/pdb/1crn.pdb'";
  const auto area_of = [&](const std::string& options) {
    const auto r = run_molsurf("-q --areas-only --json a.json " + options + " " + file, dir.path());
    EXPECT_EQ(r.exit_code, 0) << options << "\n" << r.err;
    return read_text(dir.path() / "a.json");
  };
  const std::string by_name = area_of("--radii naccess"), by_set = area_of("--radius-set naccess");
  EXPECT_EQ(json_number(by_name, "area"), json_number(by_set, "area"));
  EXPECT_NE(json_number(by_name, "area"), json_number(area_of(""), "area"));
  // Two configurations that differ only in the class of CA: the same area, and the CA atoms'
  // share moves from apolar to polar.
  for (const char* cls : {"apolar", "polar"}) {
    std::ofstream(dir.path() / (std::string(cls) + ".config"))
        << "name: test\ntypes:\nCA_TYPE 1.88 " << cls << "\nO 1.42 polar\natoms:\nANY CA CA_TYPE\nANY O O\n";
  }
  const std::string apolar = area_of("--config-file apolar.config"), polar = area_of("--config-file polar.config");
  EXPECT_EQ(json_number(apolar, "area"), json_number(polar, "area"));
  const double moved = json_number(polar, "polar") - json_number(apolar, "polar");
  EXPECT_GT(moved, 10);
  EXPECT_NEAR(json_number(apolar, "apolar") - json_number(polar, "apolar"), moved, 1e-6);
  const auto missing = run_molsurf("--areas-only --radii nosuchset " + file, dir.path());
  EXPECT_NE(missing.exit_code, 0);  // not a set, and no such file
  EXPECT_NE(missing.err.find("nosuchset"), std::string::npos) << missing.err;
}

// --format: FreeSASA's reports on standard output and no mesh; --depth lists residues and atoms.
TEST(CliAreas, FreeSasaFormatsOnStandardOutputWithoutAMesh) {
  TempDir dir;
  const std::string file = "'" + kData + "/pdb/1crn.pdb'";
  const auto json = run_molsurf("--format json --depth atom " + file, dir.path());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));  // no mesh, no file
  const double area = json_number(json.out, "area");
  // 327 atoms, whose areas add up to the total; 46 residues.
  std::size_t atoms = 0;
  double sum = 0;
  for (std::size_t at = json.out.find("\"serial\""); at != std::string::npos; at = json.out.find("\"serial\"", at + 1)) {
    ++atoms;
    sum += json_number(json.out.substr(at), "area");
  }
  EXPECT_EQ(atoms, 327u);
  EXPECT_NEAR(sum, area, 1e-9 * area);
  const auto rsa = run_molsurf("--format rsa --format seq " + file, dir.path());
  ASSERT_EQ(rsa.exit_code, 0) << rsa.err;
  std::istringstream lines(rsa.out);
  std::size_t res = 0, seq = 0;
  double total = -1;
  for (std::string line; std::getline(lines, line);) {
    res += line.rfind("RES ", 0) == 0;
    seq += line.rfind("SEQ ", 0) == 0;
    if (line.rfind("TOTAL", 0) == 0) total = std::stod(line.substr(5));
  }
  EXPECT_EQ(res, 46u);
  EXPECT_EQ(seq, 46u);
  EXPECT_NEAR(total, area, 0.05);
  EXPECT_LT(rsa.out.find("REM "), rsa.out.find("# Residues"));  // in the order given
  const auto twice = run_molsurf("--format rsa --json - " + file, dir.path());
  EXPECT_NE(twice.exit_code, 0);  // one report on standard output at most
  const auto models = run_molsurf("--format rsa --all-models " + file, dir.path());
  EXPECT_NE(models.exit_code, 0);
  EXPECT_NE(models.err.find("--format"), std::string::npos) << models.err;
}

// The progress bar: each stage with its percent on stderr, on a terminal or with --progress,
// never with -q, nothing when stderr is a file and --progress is not given.
TEST(CliProgress, StagesOnATerminalOrWhenAskedAndSilenceOtherwise) {
  TempDir dir;
  const std::string file = "'" + kData + "/pdb/1crn.pdb'";
  const auto forced = run_molsurf("--progress -o s.vtp " + file, dir.path());
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  for (const char* stage : {"union ", "cleanup ", "check ", "measures "})
    EXPECT_NE(forced.err.find(std::string("\r") + stage), std::string::npos) << stage << "\n" << forced.err;
  EXPECT_NE(forced.err.find("100%"), std::string::npos);
  const auto plain = run_molsurf("-o s.vtp " + file, dir.path());
  EXPECT_EQ(plain.err.find("100%"), std::string::npos) << plain.err;
  const auto quiet = run_molsurf("-q --progress -o s.vtp " + file, dir.path());
  EXPECT_EQ(quiet.err, "");
  // Under a pseudo-terminal (util-linux script): the bar without being asked; -q silences it.
  if (std::system("command -v script > /dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) for a pseudo-terminal";
  const std::string tty = "script -qec \"'" MOLSURF_CLI_PATH "' -o s.vtp " + file + "\" /dev/null";
  const auto on_tty = run_molsurf("--version", dir.path(), tty + " > tty.txt 2>&1; ");
  EXPECT_NE(read_text(dir.path() / "tty.txt").find("measures [###"), std::string::npos) << read_text(dir.path() / "tty.txt");
  const std::string tty_quiet = "script -qec \"'" MOLSURF_CLI_PATH "' -q -o s.vtp " + file + "\" /dev/null";
  run_molsurf("--version", dir.path(), tty_quiet + " > tty_quiet.txt 2>&1; ");
  EXPECT_EQ(read_text(dir.path() / "tty_quiet.txt").find("[#"), std::string::npos) << read_text(dir.path() / "tty_quiet.txt");
}

}  // namespace
}  // namespace molsurf
