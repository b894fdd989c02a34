// bench_boolean: runs the union engine on the paper's Table I workloads and on degenerate
// configurations, and prints one table of per-step times (best of N runs), output sizes,
// the paper's times where it has them, and whether the result is a valid closed mesh.
//
//   bench_boolean [--op union|intersection|difference] [--repeat N] [--threads N]
//                 [--filter TEXT] [--markdown] [--no-check]
//
// --filter keeps the workloads whose name contains TEXT; --no-check skips validating the
// operands and the result (for profilers: check_mesh costs several times the Boolean itself).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "molsurf/boolean.hpp"
#include "molsurf/mesh_check.hpp"
#include "table1_workloads.hpp"

namespace {

using molsurf::BooleanOp;
using molsurf::BooleanResult;
using molsurf::bench::Workload;

struct Options {
  BooleanOp op = BooleanOp::union_;
  int repeat = 3;
  int threads = 0;  // 0: OpenMP's default
  std::string filter;
  bool markdown = false;
  bool check = true;  // --no-check skips check_mesh, which dominates a profile otherwise
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "bench_boolean: " << problem << "\n"
            << "usage: bench_boolean [--op union|intersection|difference] [--repeat N] [--threads N]\n"
            << "                     [--filter TEXT] [--markdown] [--no-check]\n";
  std::exit(2);
}

int positive_int(std::string_view flag, const char* text) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 1 || value > 1'000'000) usage(std::string(flag) + " needs a positive integer");
  return static_cast<int>(value);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(std::string(arg) + " needs a value");
      return argv[++i];
    };
    if (arg == "--op") {
      const std::string_view v = value();
      if (v == "union") o.op = BooleanOp::union_;
      else if (v == "intersection") o.op = BooleanOp::intersection;
      else if (v == "difference") o.op = BooleanOp::difference;
      else usage("unknown --op " + std::string(v));
    } else if (arg == "--repeat") {
      o.repeat = positive_int(arg, value());
    } else if (arg == "--threads") {
      o.threads = positive_int(arg, value());
    } else if (arg == "--filter") {
      o.filter = value();
    } else if (arg == "--markdown") {
      o.markdown = true;
    } else if (arg == "--no-check") {
      o.check = false;
    } else if (arg == "--help" || arg == "-h") {
      usage("help");
    } else {
      usage("unknown argument " + std::string(arg));
    }
  }
  return o;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

// Milliseconds with enough digits to read small steps without drowning large ones.
std::string ms(double seconds) {
  const double v = seconds * 1e3;
  return fixed(v, v < 10 ? 2 : (v < 100 ? 1 : 0));
}

struct Measurement {
  std::optional<BooleanResult> best;  // the fastest run (by wall time)
  double best_wall = 0;
  std::string error;                  // what the engine threw, if it did
};

Measurement measure(const Workload& w, BooleanOp op, int repeat) {
  Measurement m;
  for (int r = 0; r < repeat; ++r) {
    try {
      const auto start = std::chrono::steady_clock::now();
      BooleanResult result = molsurf::boolean(w.a, w.b, op);
      // Wall time includes what the engine's step timer does not see: freeing the
      // intermediate arrangement and split faces on return.
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!m.best || wall < m.best_wall) {
        m.best = std::move(result);
        m.best_wall = wall;
      }
    } catch (const std::exception& e) {
      m.error = e.what();
      m.best.reset();
      return m;  // a throwing workload throws every time: repeating it says nothing new
    }
  }
  return m;
}

// Table cells are short; anything long (defects, exception messages) goes to numbered
// notes printed under the table.
struct Notes {
  std::vector<std::string> lines;
  std::string add(const std::string& text) {
    lines.push_back(text);
    // Built by appending: GCC 12 warns (-Wrestrict, a false positive) on "literal" + string&&.
    std::string ref = "[";
    ref += std::to_string(lines.size());
    ref += "]";
    return ref;
  }
};

std::string defects_text(const molsurf::MeshCheck& check) {
  std::string text;
  for (const std::string& d : check.defects()) text += (text.empty() ? "" : "; ") + d;
  return text;
}

// The most output faces that come from one input face: the size of the largest face
// re-triangulation, which is what the split step's cost grows with.
std::size_t max_pieces(const BooleanResult& result) {
  std::map<std::pair<std::uint8_t, std::uint32_t>, std::size_t> count;
  std::size_t most = 0;
  for (std::size_t f = 0; f < result.face_source.size(); ++f)
    most = std::max(most, ++count[{result.face_operand[f], result.face_source[f]}]);
  return most;
}

void print_table(const std::vector<std::vector<std::string>>& rows, bool markdown) {
  std::vector<std::size_t> width(rows.front().size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  auto cell = [&](const std::string& text, std::size_t c) {
    // Names left-aligned, numbers right-aligned, as a reader scans them.
    const std::string pad(width[c] - text.size(), ' ');
    return c == 0 ? text + pad : pad + text;
  };
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = markdown ? "|" : "";
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      if (markdown)
        line += " ";
      else if (c > 0)
        line += "  ";
      line += cell(rows[r][c], c);
      line += markdown ? " |" : "";
    }
    std::cout << line << "\n";
    if (r == 0) {
      if (markdown) {
        line = "|";
        for (std::size_t c = 0; c < width.size(); ++c) {
          // Left-align the name column, right-align the numbers.
          line += c == 0 ? ":" : "";
          line += std::string(width[c] + 1, '-');
          line += c == 0 ? "|" : ":|";
        }
      } else {
        std::size_t total = 0;
        for (std::size_t w : width) total += w + 2;
        line = std::string(total - 2, '-');
      }
      std::cout << line << "\n";
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  if (options.threads > 0) omp_set_num_threads(options.threads);

  std::vector<std::vector<std::string>> rows;
  rows.push_back({"workload", "faces A", "faces B", "faces out", "cand pairs", "isect pts", "split faces", "max pieces", "cull ms", "intersect ms", "split ms",
                  "classify ms", "stitch ms", "total ms", "wall ms", "paper isect/total s", "valid"});
  Notes notes;

  for (const Workload& w : molsurf::bench::all_workloads()) {
    if (!options.filter.empty() && w.name.find(options.filter) == std::string::npos) continue;
    std::cerr << "running " << w.name << " ..." << std::endl;

    // A workload whose operands break the engine's contract measures nothing useful; say so.
    for (const auto* operand : {&w.a, &w.b}) {
      if (!options.check) break;
      const molsurf::MeshCheck check = molsurf::check_mesh(*operand);
      if (!check.valid())
        notes.add(w.name + ": operand " + (operand == &w.a ? "A" : "B") + " is invalid: " + defects_text(check));
    }

    const Measurement m = measure(w, options.op, options.repeat);
    const std::string paper =
        w.paper ? fixed(w.paper->intersection, 2) + " / " + fixed(w.paper->total, 1) : std::string("-");
    std::vector<std::string> row{w.name, std::to_string(w.a.face_count()), std::to_string(w.b.face_count())};
    if (!m.best) {
      const std::string ref = notes.add(w.name + ": the engine threw: " + m.error + " (" + w.description + ")");
      for (int c = 0; c < 12; ++c) row.push_back("-");
      row.push_back(paper);
      row.push_back("threw " + ref);
    } else {
      const molsurf::BooleanStats& s = m.best->stats;
      // Validated once, outside the timing: check_mesh's self-intersection test costs more
      // than the Boolean itself.
      std::string valid = "not checked";
      if (options.check) {
        const molsurf::MeshCheck check = molsurf::check_mesh(m.best->mesh);
        valid = "yes";
        if (!check.valid())
          valid = "NO " + notes.add(w.name + ": result invalid: " + defects_text(check) + " (" + w.description + ")");
      }
      row.insert(row.end(), {std::to_string(s.output_faces), std::to_string(s.candidate_pairs),
                             std::to_string(s.intersection_points), std::to_string(s.split_faces),
                             std::to_string(max_pieces(*m.best)),
                             ms(s.seconds.cull), ms(s.seconds.intersect), ms(s.seconds.split),
                             ms(s.seconds.classify), ms(s.seconds.stitch), ms(s.seconds.total()), ms(m.best_wall),
                             paper, valid});
    }
    rows.push_back(std::move(row));
  }
  if (rows.size() == 1) usage("no workload matches --filter " + options.filter);

  std::cout << (options.markdown ? "" : "# ") << "op " << molsurf::boolean_op_name(options.op) << ", best of "
            << options.repeat << ", " << omp_get_max_threads() << " OpenMP thread(s)\n\n";
  print_table(rows, options.markdown);
  if (!notes.lines.empty()) {
    std::cout << "\n";
    for (std::size_t i = 0; i < notes.lines.size(); ++i)
      std::cout << (options.markdown ? "" : "  ") << "[" << i + 1 << "] " << notes.lines[i] << "\n";
  }
  return 0;
}
