"""The Python module (docs/python.md) against the run it drives: decks and their errors, a run's
results as arrays, the progress callback, stopping and restarting, the GIL, verification."""

import os
import signal
import threading
import time

import numpy
import pytest

import kessler

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ELASTIC = os.path.join(ROOT, "tests", "data", "decks", "elastic-sphere-plate.yaml")
SHORT = {"solver.end_time": "1 us", "output.every": "0.5 us"}

# A small deck as a dict: the elastic sphere and plate, 1.5 mm spacing.
DICT_DECK = {
    "title": "dict deck",
    "materials": {"al": {"model": "neo-hookean", "density": "2700 kg/m^3", "youngs_modulus": "70 GPa",
                         "poisson_ratio": 0.33}},
    "bodies": [
        {"name": "projectile", "material": "al", "shape": {"sphere": {"center": [0, 0, "5.2 mm"], "radius": "5 mm"}},
         "velocity": [0, 0, "-300 m/s"], "mesh_size": "1.5 mm"},
        {"name": "plate", "material": "al",
         "shape": {"box": {"min": ["-15 mm", "-15 mm", "-3 mm"], "max": ["15 mm", "15 mm", 0]}},
         "mesh_size": "1.5 mm", "fixed": "lateral-faces"},
    ],
    "symmetry": ["x", "y"],
    "solver": {"method": "otm", "end_time": "1 us"},
    "output": {"every": "0.5 us", "dir": "unused"},
}


def test_deck_from_file_dict_and_text():
    d = kessler.deck(ELASTIC, SHORT)
    assert d.method == "otm" and d.bodies == ["projectile", "plate"]
    assert d.end_time == pytest.approx(1e-6, rel=1e-12)
    from_dict = kessler.deck(DICT_DECK)
    assert from_dict.title == "dict deck" and from_dict.end_time == pytest.approx(1e-6, rel=1e-12)
    from_text = kessler.deck(from_dict.yaml())
    assert from_text.yaml() == from_dict.yaml()
    assert kessler.deck(d) is not d  # a copy: run(out=...) does not change the caller's deck


def test_bad_decks_say_where_and_why():
    with pytest.raises(kessler.InputError) as e:
        kessler.deck(os.path.join(ROOT, "tests", "data", "decks", "bad_cfl.yaml"))
    assert "bad_cfl.yaml:10:33: solver.cfl: must lie in (0, 1] (got '1.5')" in str(e.value)
    bad = dict(DICT_DECK, solver={"method": "otm", "end_time": "-1 us"})
    with pytest.raises(ValueError) as e:  # InputError is a ValueError
        kessler.deck(bad)
    assert str(e.value).startswith("deck (dict):") and "solver.end_time" in str(e.value) and "-1 us" in str(e.value)
    with pytest.raises(kessler.InputError, match="command line"):
        kessler.deck(ELASTIC, {"solver.no_such_key": 1})


def test_run_gives_fields_analysis_and_tables(tmp_path):
    calls = []
    r = kessler.run(DICT_DECK, out=tmp_path / "run", threads=2, quiet=True, progress=lambda *a: calls.append(a))
    assert r.status == "completed"
    # An output comes at the first step that reaches its time: 0, 0.5 us (within a step), the end.
    times = r.times
    assert len(times) == 3 and times[0] == 0.0 and times[2] == pytest.approx(1e-6, rel=1e-12)
    assert 0.5e-6 <= times[1] < 0.5e-6 + r.history["dt_s"].max()
    points = r.summary["problem"]["points"]
    frame = r.points(-1)
    assert frame["position"].shape == (points, 3) and frame["pressure"].shape == (points,)
    assert "temperature" in frame and frame.time == pytest.approx(1e-6)
    nodes = r.nodes(-1)
    # The nodes carry the whole mass of the quarter model: the sphere's and the plate's.
    mass = 2700.0 * (numpy.pi * 0.005**3 / 3 + 0.015 * 0.015 * 0.003)
    assert nodes["mass"].sum() == pytest.approx(mass, rel=0.02)
    assert r.analysis["debris"] is False  # an elastic rebound breaks nothing
    history = r.history
    assert history["step"][0] == 0 and history["time_s"][-1] == pytest.approx(1e-6)
    fragments = r.fragments
    assert sorted(fragments["body"]) == ["plate", "projectile"]
    # The callback: increasing steps, the end time passed along, the last call at the end.
    steps = [c[0] for c in calls]
    assert steps == sorted(steps) and calls[-1][1] == pytest.approx(1e-6) and calls[-1][2] == pytest.approx(1e-6)


def test_a_callback_stops_the_run_and_restart_continues_it(tmp_path):
    out = tmp_path / "stopped"
    r = kessler.run(ELASTIC, out=out, sets=SHORT, quiet=True, progress=lambda step, *rest: step < 5,
                    progress_interval=0)
    assert r.status == "interrupted" and os.path.exists(out / "checkpoint.h5")
    assert r.history["time_s"][-1] < 1e-6
    done = kessler.restart(out, quiet=True, progress=False)
    assert done.status == "completed" and done.history["time_s"][-1] == pytest.approx(1e-6)
    longer = kessler.restart(out, end_time="1.5 us", quiet=True, progress=False)
    assert longer.history["time_s"][-1] == pytest.approx(1.5e-6)
    with pytest.raises(kessler.InputError, match="only these may change"):
        kessler.restart(out, sets={"bodies.0.mesh_size": "1 mm"})


def test_an_exception_in_the_callback_stops_the_run_cleanly(tmp_path):
    class Stop(Exception):
        pass

    def callback(step, *rest):
        if step >= 3:
            raise Stop("enough")
        return True

    out = tmp_path / "raised"
    with pytest.raises(Stop):
        kessler.run(ELASTIC, out=out, sets=SHORT, quiet=True, progress=callback, progress_interval=0)
    # Nothing lost: the state it reached is in the checkpoint, which continues it.
    r = kessler.Results(out)
    assert r.status == "interrupted" and os.path.exists(out / "checkpoint.h5")
    # A run still going has written no summary yet: its outputs are readable, its status None.
    os.rename(out / "summary.json", out / "summary.saved")
    assert r.status is None and r.analysis == {} and len(r.times) >= 1
    os.rename(out / "summary.saved", out / "summary.json")
    assert kessler.restart(out, quiet=True, progress=False).status == "completed"


def test_ctrl_c_writes_the_state_and_raises_keyboard_interrupt(tmp_path):
    sent = []

    def callback(step, *rest):
        if step >= 3 and not sent:  # (a second Ctrl-C ends the process at once, by design)
            sent.append(step)
            os.kill(os.getpid(), signal.SIGINT)
        return True

    out = tmp_path / "interrupted"
    with pytest.raises(KeyboardInterrupt, match="restart"):
        kessler.run(ELASTIC, out=out, sets=SHORT, quiet=True, progress=callback, progress_interval=0)
    assert kessler.Results(out).status == "interrupted" and os.path.exists(out / "checkpoint.h5")


def test_the_gil_is_released_while_the_solver_runs(tmp_path):
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.005)

    thread = threading.Thread(target=ticker)
    thread.start()
    try:
        start = time.monotonic()
        kessler.run(ELASTIC, out=tmp_path / "gil", sets={"solver.end_time": "4 us"}, threads=1, quiet=True,
                    progress=False)
        end = time.monotonic()
    finally:
        stop.set()
        thread.join()
    during = [t for t in ticks if start < t < end]
    # The Python thread kept running during the run (with the GIL held it would tick at most once):
    # at least a tenth of the ticks it makes alone, so that a loaded machine's late wake-ups pass.
    assert end - start > 0.1 and len(during) >= 0.1 * (end - start) / 0.005


def test_verify_returns_the_measurements():
    [outcome] = kessler.verify(["lme-consistency"], progress=False)
    assert outcome["name"] == "lme-consistency" and outcome["passed"] is True
    assert outcome["error"] <= outcome["tolerance"]
    with pytest.raises(kessler.InputError, match="unknown verification problem"):
        kessler.verify(["no-such-problem"])
    with pytest.raises(kessler.InputError, match="not a method"):
        kessler.verify(["lme-consistency"], method="fem")


def test_bench_measures_in_a_fresh_process():
    result = kessler.bench("hvi-100k", size="tiny", threads=1)
    [problem] = result["problems"]
    assert problem["status"] == "ok" and problem["points"] > 1000
    assert problem["us_per_point_step"] > 0 and problem["peak_model_bytes_per_point"] > 0
    with pytest.raises(kessler.InputError, match="hvi-100k"):  # the error names the known problems
        kessler.bench("no-such-problem", size="tiny")
