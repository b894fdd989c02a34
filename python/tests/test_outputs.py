"""Writes from Python: a signal that ends the interpreter in the middle of a write leaves no
temporary file, and residue numbers keep their full range."""
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
