// molsurf: the command line. It only parses options and calls the library.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>

#include "blocks/first_process_verdict.hpp"
#include "cli/allocation.hpp"
#include "cli/commands.hpp"
#include "cli/mpi/message_passing.hpp"
#include "cli/validators.hpp"
#include "molsurf/error.hpp"
#include "molsurf/output_files.hpp"
#include "io/standard_output.hpp"
#include "molsurf/parameters.hpp"

int main(int argc, char** argv) {
  using namespace molsurf::cli;
  molsurf::guard_standard_streams();  // before anything opens a file
  use_large_pages();
  // Under mpirun or srun: the surface's blocks shared by the launched processes.
  const std::unique_ptr<molsurf::blocks::BlockExchange> message_passing = start_message_passing(argc, argv);
  CLI::App app{
      "molsurf " MOLSURF_VERSION " - exact, watertight molecular surfaces.\n"
      "The solvent-accessible surface of a structure is the union of one sphere per atom\n"
      "(radius r_vdW + probe), each triangulated as an icosphere, joined by exact mesh union.\n\n"
      "Usage:\n"
      "  molsurf [OPTIONS] STRUCTURE        surface of a .pdb .cif .pqr .xyzr file (.gz too)\n"
      "  molsurf check [OPTIONS] MESH       is a mesh a valid closed surface?\n"
      "  molsurf boolean OP A B -o OUT      union | intersection | difference of two meshes\n"
      "  molsurf batch LIST|DIR -o OUTDIR   every structure of a list or folder, several at a time",
      "molsurf"};
  app.set_version_flag("--version", "molsurf " MOLSURF_VERSION);
  app.require_subcommand(0, 1);
  app.get_formatter()->column_width(34);

  SurfaceCommand surface;
  surface.add_options(app);

  CheckCommand check;
  CLI::App* check_app = app.add_subcommand(
      "check",
      "Read any mesh (.vtp .vtk .ply .off .stl .obj .vert/.face .msh, or a .pvtp index of pieces, glued\n"
      "at their seams) and report whether it is a valid closed surface:\n"
      "closed, edge- and vertex-manifold, consistently oriented outward, no degenerate face and\n"
      "no self-intersection (decided with exact predicates). Exit status 0 only for a valid surface.");
  check.add_options(*check_app);

  BooleanCommand boolean;
  CLI::App* boolean_app = app.add_subcommand(
      "boolean",
      "Union, intersection or difference of two closed meshes (any readable format), by the exact\n"
      "engine; prints the result's validation, area, volume and the time of each step.");
  boolean.add_options(*boolean_app);

  BatchCommand batch;
  CLI::App* batch_app = app.add_subcommand(
      "batch",
      "Run molsurf on every structure of a list or folder, several at a time, each in its own process:\n"
      "a failure is recorded and the rest go on; a rerun skips what is done (manifest.tsv). Summary:\n"
      "summary.csv and summary.jsonl in the output folder. Exit status 0 when none failed.\n"
      "Under MPI (mpirun -np N molsurf batch LIST -o OUTDIR) the first process hands the structures\n"
      "out one at a time to whichever process is free (itself too) and alone writes the manifest\n"
      "and the summary.");
  batch.add_options(*batch_app);

  // Usage errors in one line, like every other error (CLI11_PARSE adds a second).
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "molsurf: error: " << e.what() << " (run with --help for the options)\n";
    return 2;
  }
  // A Ctrl-C (or kill) while a file is being written leaves no temporary behind.
  molsurf::remove_temporaries_on_signals();
  try {
    const bool subcommand = check_app->parsed() || boolean_app->parsed() || batch_app->parsed();
    if (surface.structure.empty() && !subcommand) {
      std::cerr << "molsurf: no structure file given\nRun with --help for more information.\n";
      return 2;
    }
    if (!subcommand) surface.cap_threads();
    if (message_passing && message_passing->size() > 1 && (check_app->parsed() || boolean_app->parsed()))
      throw molsurf::Error("under mpirun, molsurf makes one surface in blocks or runs a batch; run check and boolean alone");
    surface.exchange = message_passing.get();
    if (message_passing && message_passing->rank() != 0) surface.quiet = true;  // the first process reports
    const int status = check_app->parsed()     ? check.run()
                       : boolean_app->parsed() ? boolean.run()
                       : batch_app->parsed()   ? batch.run()
                                               : surface.run();
    // The text report is output too: a report that did not reach standard output fails the run.
    molsurf::flush_standard_output();
    return status;
  } catch (const molsurf::blocks::FirstProcessVerdict&) {
    // Under mpirun: what the first process found wrong, and printed; said once.
    return 1;
  } catch (const molsurf::ParameterError& e) {
    // A rule between options, found by the library: named as the command spells the option.
    std::cerr << "molsurf: error: " << option_spelling(e.parameter()) << ": " << e.problem() << "\n";
    return 1;
  } catch (const molsurf::Error& e) {
    std::cerr << "molsurf: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    // Memory ran out despite the up-front estimate (other programs, a low ulimit).
    std::cerr << "molsurf: error: out of memory (an allocation failed); nothing was written. Lower --density "
                 "or --frequency, select fewer atoms, or run where more memory is available\n";
    return 1;
  } catch (const std::length_error& e) {
    std::cerr << "molsurf: error: out of memory: a table would exceed the addressable size (" << e.what()
              << "); nothing was written. Lower --density or --frequency\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "molsurf: internal error: " << e.what() << "\n";
    return 1;
  }
}
