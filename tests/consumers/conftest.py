"""Shared set-up of the consumer tests: molsurf's outputs read by the programs users
give them to (docs/formats.md). MOLSURF_CLI names the molsurf binary, MOLSURF_DATA_DIR
the structures; both are set by ctest (tests/consumers/CMakeLists.txt)."""
import json
import os
import subprocess
from pathlib import Path

import pytest


def pytest_configure(config):
    config.addinivalue_line("markers", "long: slow consumer checks (ctest label 'long')")


@pytest.fixture(scope="session")
def molsurf_cli():
    cli = os.environ.get("MOLSURF_CLI")
    if not cli or not Path(cli).is_file():
        pytest.skip("MOLSURF_CLI does not name the molsurf binary (run through ctest)")
    return cli


@pytest.fixture(scope="session")
def data_dir():
    return Path(os.environ.get("MOLSURF_DATA_DIR", Path(__file__).resolve().parents[2] / "data"))


class Run:
    """One molsurf run: the files it wrote and its JSON report. report["area"], report["volume"]
    and atom_area (--per-atom's area column) are the true spheres' exact numbers;
    report["facet_area"], report["facet_volume"] and report["components"] the mesh's."""

    def __init__(self, cli, structure, directory, output, *options):
        self.directory = Path(directory)
        self.output = self.directory / output
        report = self.directory / (output + ".json")
        per_atom = self.directory / (output + ".atoms.csv")
        command = [cli, str(structure), "-o", str(self.output), "--json", str(report),
                   "--per-atom", str(per_atom), "-q", *options]
        subprocess.run(command, check=True, timeout=1200)
        self.report = json.loads(report.read_text())
        self.atom_area = [float(line.split(",")[-1]) for line in per_atom.read_text().splitlines()[1:]]


@pytest.fixture(scope="session")
def run_molsurf(molsurf_cli, tmp_path_factory):
    """run_molsurf(structure, output_name, *options) -> Run"""
    def run(structure, output, *options):
        return Run(molsurf_cli, structure, tmp_path_factory.mktemp("out"), output, *options)
    return run
