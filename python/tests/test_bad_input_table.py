"""The bad-input table (tests/data/bad_inputs/table.json, docs/api.md): every row through Python
and through the molsurf command, which must give the same verdict and the same message (each
front end naming where the value came from in its own way: an option or keyword, a file's line
or an array entry). tests/test_cli_bad_inputs.cpp holds the command alone to the same table."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import molsurf

from conftest import SOURCE_DIR

TABLE_DIR = SOURCE_DIR / "tests" / "data" / "bad_inputs"
ROWS = json.loads((TABLE_DIR / "table.json").read_text())["rows"]


def names():
    """What the table's Python column may use."""
    two = dict(centres=np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]), radii=np.array([1.5, 1.5]))
    tet = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    return dict(molsurf=molsurf, np=np, nan=float("nan"), inf=float("inf"), TWO=two, TET=tet,
                mesh=molsurf.read_mesh)


def with_where(where, message):
    return f"{where}: {message}" if where else message


def run_python(row):
    """(verdict, message) of the row's Python call."""
    try:
        eval(row["python"], names())  # noqa: S307: the table is ours
    except molsurf.Error as error:
        return "error", str(error)
    return "ok", None


def run_cli(cli, row, folder):
    """(verdict, exit status, message without the command's frame) of the row's command."""
    run = subprocess.run([str(cli), *row["cli"]], cwd=folder, capture_output=True, text=True)
    if run.returncode == 0:
        return "ok", 0, None
    line = run.stderr
    assert line.startswith("molsurf: error: ") and line.endswith("\n") and line.count("\n") == 1, run.stderr
    line = line[len("molsurf: error: "):-1]
    suffix = " (run with --help for the options)"
    if run.returncode == 2 and line.endswith(suffix):
        line = line[:-len(suffix)]
    return "error", run.returncode, line


def test_the_table_has_every_kind_of_row():
    assert len(ROWS) >= 20
    assert {row["verdict"] for row in ROWS} == {"ok", "error"}
    assert len({row["input"] for row in ROWS}) == len(ROWS)


@pytest.mark.parametrize("row", ROWS, ids=[row["input"] for row in ROWS])
def test_command_and_python_agree(row, cli, tmp_path, monkeypatch):
    cli = cli.resolve()  # a relative MOLSURF_CLI, before the folder changes
    folder = tmp_path / "inputs"
    shutil.copytree(TABLE_DIR, folder)
    monkeypatch.chdir(folder)
    py_verdict, py_message = run_python(row)
    cli_verdict, cli_exit, cli_message = run_cli(cli, row, folder)
    assert py_verdict == cli_verdict == row["verdict"], (py_message, cli_message)
    if row["verdict"] == "ok":
        return
    assert cli_exit == row["cli_exit"]
    assert py_message == with_where(row["python_where"], row["message"])
    assert cli_message == with_where(row["cli_where"], row["message"])
    # The one message, each front end's place in front of it.
    assert py_message.removeprefix(f"{row['python_where']}: ") == cli_message.removeprefix(f"{row['cli_where']}: ")


def test_docs_list_every_row():
    docs = (SOURCE_DIR / "docs" / "api.md").read_text()
    for row in ROWS:
        assert f"| {row['input']} |" in docs, row["input"]
        if row["verdict"] == "error":
            assert f"`{row['message']}`" in docs, row["input"]
