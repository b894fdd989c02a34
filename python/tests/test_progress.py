"""surface(progress=...): the stages reported to a Python callable, and its exceptions."""
import pytest

import molsurf


def test_progress_reports_every_stage_in_order(data_dir):
    calls = []
    s = molsurf.surface(data_dir / "1crn.pdb", progress=lambda stage, done, total: calls.append((stage, done, total)))
    assert s.check.valid
    assert calls, "no progress reported"
    stages = [stage for stage, _, _ in calls]
    order = ["union", "cleanup", "check", "measures"]
    assert set(stages) <= set(order)
    assert [order.index(x) for x in stages] == sorted(order.index(x) for x in stages)  # never back
    assert stages[-1] == "measures"
    for stage, done, total in calls:
        assert isinstance(stage, str) and 0 <= done <= total
    assert calls[-1][1] == calls[-1][2]  # the last state: the last stage complete


def test_an_exception_in_the_callback_stops_the_job(data_dir):
    class Stop(Exception):
        pass

    def stop(stage, done, total):
        raise Stop(stage)

    with pytest.raises(Stop):
        molsurf.surface(data_dir / "2hhb.pdb", progress=stop)


def test_a_progress_that_cannot_be_called_is_refused(data_dir):
    with pytest.raises(molsurf.Error, match="progress: must be callable"):
        molsurf.surface(data_dir / "1crn.pdb", progress=3)
