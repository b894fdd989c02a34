#include "molsurf/freesasa_formats.hpp"

#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "molsurf/atom_classes.hpp"

namespace molsurf {

namespace {

// One residue's areas by the RSA's five columns.
struct ResidueClasses {
  const Atom* first = nullptr;  // names the residue
  double all = 0, side = 0, main = 0, apolar = 0, polar = 0;
};

// Residues in order of first appearance (chain, number, insertion code and name tell them apart).
std::vector<ResidueClasses> residue_classes(std::span<const Atom> atoms, std::span<const double> area) {
  if (atoms.size() != area.size()) throw std::invalid_argument("FreeSASA formats: one area per atom");
  std::vector<ResidueClasses> out;
  std::map<std::tuple<std::string, int, char, std::string>, std::size_t> index;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const auto [it, added] =
        index.emplace(std::make_tuple(a.chain, a.residue_number, a.insertion_code, a.residue_name), out.size());
    if (added) out.push_back({&a});
    ResidueClasses& r = out[it->second];
    r.all += area[i];
    (is_main_chain(a) ? r.main : r.side) += area[i];
    (is_polar(a) ? r.polar : r.apolar) += area[i];
  }
  return out;
}

std::string line(const char* format, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, values...);
  return buffer;
}

std::string chain_name(const std::string& chain) { return chain.empty() ? "_" : chain; }

}  // namespace

std::string rsa_text(std::span<const Atom> atoms, std::span<const double> atom_area, const RsaHeader& header) {
  const std::vector<ResidueClasses> residues = residue_classes(atoms, atom_area);
  std::vector<std::string> chains;
  std::map<std::string, ResidueClasses> by_chain;
  for (const ResidueClasses& r : residues)
    if (by_chain.emplace(r.first->chain, ResidueClasses{}).second) chains.push_back(r.first->chain);
  std::string chain_list;
  for (const std::string& c : chains) chain_list += (chain_list.empty() ? "" : " ") + chain_name(c);

  std::string out = "REM  molsurf " MOLSURF_VERSION "\n";
  out += "REM  Absolute and relative SASAs for " + header.source + "\n";
  out += "REM  Atomic radii: " + header.radii + "; reference values for relative SASA: Tien et al. 2013 " +
         (header.scale == MaxAreaScale::theoretical ? "theoretical" : "empirical") + " (all atoms only)\n";
  out += "REM  Chains: " + chain_list + "\n";
  out += "REM  Algorithm: exact (the true spheres' arrangement)\n";
  out += line("REM  Probe-radius: %.2f\n", header.probe);
  out += "REM RES _ NUM      All-atoms   Total-Side   Main-Chain    Non-polar    All polar\n";
  out += "REM                ABS   REL    ABS   REL    ABS   REL    ABS   REL    ABS   REL\n";
  for (const ResidueClasses& r : residues) {
    const Atom& a = *r.first;
    const std::optional<double> max = max_residue_area(a.residue_name, header.scale);
    std::string relative = max ? line("%6.1f", 100 * r.all / *max) : line("%6s", "N/A");
    out += line("RES %-3s %s%4lld%c%8.2f", a.residue_name.c_str(), chain_name(a.chain).c_str(),
                static_cast<long long>(a.residue_number),
                a.insertion_code, r.all) +
           relative;
    for (const double value : {r.side, r.main, r.apolar, r.polar}) out += line("%7.2f%6s", value, "N/A");
    out += "\n";
    ResidueClasses& c = by_chain[a.chain];
    c.all += r.all, c.side += r.side, c.main += r.main, c.apolar += r.apolar, c.polar += r.polar;
  }
  out += "END  Absolute sums over single chains surface\n";
  ResidueClasses total;
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const ResidueClasses& c = by_chain[chains[k]];
    out += line("CHAIN%3zu %s %10.1f   %10.1f   %10.1f   %10.1f   %10.1f\n", k + 1, chain_name(chains[k]).c_str(), c.all,
                c.side, c.main, c.apolar, c.polar);
    total.all += c.all, total.side += c.side, total.main += c.main, total.apolar += c.apolar, total.polar += c.polar;
  }
  out += "END  Absolute sums over all chains\n";
  out += line("TOTAL      %10.1f   %10.1f   %10.1f   %10.1f   %10.1f\n", total.all, total.side, total.main, total.apolar,
              total.polar);
  return out;
}

std::string residue_sequence_text(std::span<const Atom> atoms, std::span<const double> atom_area,
                                  const std::string& source) {
  std::string out = "# Residues in " + source + "\n";
  for (const ResidueClasses& r : residue_classes(atoms, atom_area)) {
    const Atom& a = *r.first;
    out += line("SEQ %s %4lld%c %3s : %7.2f\n", chain_name(a.chain).c_str(),
                static_cast<long long>(a.residue_number), a.insertion_code,
                a.residue_name.c_str(), r.all);
  }
  return out;
}

std::string residue_type_text(std::span<const Atom> atoms, std::span<const double> atom_area,
                              const std::string& source) {
  std::map<std::string, double> by_type;
  for (const char* name : {"ALA", "ARG", "ASN", "ASP", "CYS", "GLN", "GLU", "GLY", "HIS", "ILE",
                           "LEU", "LYS", "MET", "PHE", "PRO", "SER", "THR", "TRP", "TYR", "VAL"})
    by_type[name] = 0;
  for (const ResidueClasses& r : residue_classes(atoms, atom_area)) by_type[r.first->residue_name] += r.all;
  std::string out = "# Residue types in " + source + "\n";
  for (const auto& [name, area] : by_type) out += line("RES %s : %10.2f\n", name.c_str(), area);
  return out;
}

}  // namespace molsurf
