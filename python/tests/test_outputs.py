"""Writes from Python: the same files as the command writes, a signal that ends the interpreter
in the middle of a write leaves no temporary file, and residue numbers keep their full range."""
import os
import signal
import subprocess
import sys
import textwrap

import molsurf

# The child imports molsurf as this interpreter does (ctest's PYTHONPATH, or the build's).
CHILD_ENV = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))


def run_child(script, cwd):
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], cwd=cwd, env=CHILD_ENV,
                          capture_output=True, text=True, timeout=600)


def test_the_command_and_python_write_the_same_files(tmp_path, data_dir, cli, crambin):
    # One library call writes a surface's file for both (surface_files.hpp): the MSMS header
    # names the surface and its source, --no-header and msms_header=False drop the header and
    # the atom names alike.
    structure = data_dir / "1crn.pdb"
    for name, cli_options, python_options in [("s.vert", [], {}), ("s.vtp", [], {}), ("s.ply", ["--ascii"], {"ascii": True}),
                                              ("n.vert", ["--no-header"], {"msms_header": False})]:
        (tmp_path / "cli").mkdir(exist_ok=True)
        run = subprocess.run([str(cli), "-q", structure, "-o", tmp_path / "cli" / name, *cli_options],
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        written = crambin.write(tmp_path / name, **python_options)
        assert written
        for file in written:
            assert file.read_bytes() == (tmp_path / "cli" / file.name).read_bytes(), file.name
    header = (tmp_path / "s.vert").read_text().splitlines()[0]
    assert header.startswith("# MSMS-format vertices of the solvent accessible surface for 1crn.pdb")
    rows = (tmp_path / "n.vert").read_text().splitlines()
    assert not rows[0].startswith("#") and all(len(row.split()) == 9 for row in rows[:100])


def test_file_size_signal_during_a_write_leaves_no_temporary(tmp_path, data_dir):
    # Python ignores SIGXFSZ; the child gives it back its default (end the process), then
    # writes past a 4 KiB limit: the kernel sends SIGXFSZ in the middle of the write.
    result = run_child(f"""
        import resource, signal
        signal.signal(signal.SIGXFSZ, signal.SIG_DFL)
        import molsurf
        s = molsurf.surface({str(data_dir / "1crn.pdb")!r})
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
        s.write("big.obj")
        """, tmp_path)
    assert result.returncode == -signal.SIGXFSZ, result.stderr
    assert sorted(os.listdir(tmp_path)) == [], "temporary left behind"


def test_sigterm_during_a_write_leaves_no_temporary(tmp_path, data_dir):
    # A thread waits for the write's temporary to appear, then ends the process with SIGTERM
    # (the write runs without the GIL, so the thread runs meanwhile).
    script = f"""
        import os, signal, threading
        import molsurf
        s = molsurf.surface({str(data_dir / "2hhb.pdb")!r})
        def kill_when_writing():
            while True:
                if any(".tmp-" in name for name in os.listdir(".")):
                    os.kill(os.getpid(), signal.SIGTERM)
        threading.Thread(target=kill_when_writing, daemon=True).start()
        for k in range(20):
            s.write(f"big{{k}}.obj")
        """
    result = run_child(script, tmp_path)
    assert result.returncode == -signal.SIGTERM, result.stderr
    assert [name for name in os.listdir(tmp_path) if ".tmp-" in name] == []


def test_residue_numbers_beyond_32_bits(tmp_path):
    cif = tmp_path / "wide.cif"
    cif.write_text("data_wide\nloop_\n_atom_site.group_PDB\n_atom_site.type_symbol\n_atom_site.label_atom_id\n"
                   "_atom_site.label_comp_id\n_atom_site.auth_asym_id\n_atom_site.auth_seq_id\n"
                   "_atom_site.Cartn_x\n_atom_site.Cartn_y\n_atom_site.Cartn_z\n"
                   "ATOM C CA ALA A 3000000000 0 0 0\nATOM C CA GLY A -5000000000 3 0 0\n")
    a = molsurf.areas(str(cif))
    assert list(a.structure.residue_numbers) == [3_000_000_000, -5_000_000_000]
    assert list(a.area_per_residue["residue_number"]) == [3_000_000_000, -5_000_000_000]
