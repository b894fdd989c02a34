"""One version everywhere: CMakeLists.txt's project(), the module, the command."""
import re
import subprocess

import molsurf


def test_version_is_the_cmake_projects(source_dir):
    text = (source_dir / "CMakeLists.txt").read_text()
    match = re.search(r"project\(molsurf VERSION ([0-9.]+) ", text)
    assert match
    assert molsurf.__version__ == match.group(1)


def test_command_prints_the_same_version(cli):
    run = subprocess.run([str(cli), "--version"], capture_output=True, text=True, check=True)
    assert run.stdout.strip() == f"molsurf {molsurf.__version__}"
