"""Decks and runs: kessler.deck, kessler.run, kessler.restart, kessler.verify, kessler.bench."""

import json
import os
import subprocess
import sys
import tempfile
import time as _time

from ._core import _kessler
from .results import Results


def _overrides(sets):
    """{"solver.end_time": "2 us", "bodies.0.velocity": [0, 0, -5000]} -> ["solver.end_time=2 us", ...]."""
    if not sets:
        return []
    if isinstance(sets, dict):
        out = []
        for key, value in sets.items():
            text = value if isinstance(value, str) else json.dumps(value)
            out.append(f"{key}={text}")
        return out
    return [str(s) for s in sets]


def deck(source, sets=None):
    """A checked deck from a YAML file, YAML text or a dict (the deck's YAML tree as Python values).

    `sets` are settings on top, as `kessler run --set` takes them: a dict {"solver.end_time": "5 us"}
    or a list of "key=value" strings. A bad deck raises kessler.InputError with the message the
    command line prints: the file (or "deck (dict)"), the line and column, the key and the value.
    """
    overrides = _overrides(sets)
    if isinstance(source, _kessler.Deck):
        if overrides:
            raise ValueError("kessler.deck: settings apply to a deck being read; pass the file, text or dict")
        return source.copy()
    if isinstance(source, dict):
        # YAML reads JSON: one key per line, so that an error's line number finds its key.
        return _kessler.parse_deck(json.dumps(source, indent=2), "deck (dict)", overrides)
    if isinstance(source, os.PathLike):
        return _kessler.load_deck(os.fspath(source), overrides)
    if isinstance(source, str):
        if "\n" in source or ":" in source and not os.path.exists(source):
            return _kessler.parse_deck(source, "deck (text)", overrides)
        return _kessler.load_deck(source, overrides)
    raise TypeError(f"kessler.deck: a file name, YAML text or a dict, not {type(source).__name__}")


class _Bar:
    """A progress bar: tqdm's where Debian's python3-tqdm is installed, else one line on stderr."""

    def __init__(self, label):
        self.label = label
        self.tqdm = None
        self.start = _time.monotonic()
        try:
            from tqdm.auto import tqdm
            self.tqdm = tqdm(total=100, desc=label, unit="%", bar_format="{l_bar}{bar}| {postfix} [{elapsed}<{remaining}]")
        except ImportError:
            pass

    def __call__(self, step, time, end_time, dt):
        percent = 100.0 * time / end_time if end_time > 0 else 0.0
        if self.tqdm is not None:
            self.tqdm.n = round(percent, 1)
            self.tqdm.set_postfix_str(f"step {step}, t = {time:.3g} s", refresh=False)
            self.tqdm.refresh()
        else:
            filled = int(percent // 4)
            elapsed = _time.monotonic() - self.start
            eta = elapsed * (100.0 - percent) / percent if percent > 0 else 0.0
            sys.stderr.write(f"\r{self.label} [{'#' * filled}{'.' * (25 - filled)}] {percent:5.1f}%  step {step}  "
                             f"t = {time:.3g} s  ETA {eta:.0f} s ")
            sys.stderr.flush()
        return True

    def close(self):
        if self.tqdm is not None:
            self.tqdm.close()
        else:
            sys.stderr.write("\n")
            sys.stderr.flush()


def _execute(config, threads, progress, quiet, restart, interval):
    bar = None
    callback = None
    if callable(progress):
        callback = progress
    elif progress:
        bar = callback = _Bar(config.title or "kessler")
    try:
        folder, code, by_caller = _kessler.run(config, threads=threads, quiet=quiet, restart=restart,
                                               callback=callback, interval=interval)
    finally:
        if bar is not None:
            bar.close()
    if code != 0 and not by_caller:
        # Ctrl-C (or SIGTERM) reached the run: it wrote a checkpoint of its state before stopping.
        message = (f"the run stopped by signal {code - 128}; a checkpoint of its state is in {folder}: "
                   f"kessler.restart('{folder}') continues it")
        if code == 130:
            raise KeyboardInterrupt(message)
        raise RuntimeError(message)
    return Results(folder)


def run(source, out=None, threads=0, progress=True, sets=None, quiet=False, progress_interval=0.2):
    """Runs a deck (a kessler.Deck, or what kessler.deck takes) and returns its kessler.Results.

    out: the run folder (default: the deck's output.dir). threads: OpenMP threads (0: all).
    progress: True for a progress bar, False for none, or a function f(step, time, end_time, dt)
    called at most every progress_interval seconds (0: after every step) and after the last step;
    it returns False (or raises) to stop the run, which then writes
    a checkpoint of its state as an interrupted run does (kessler.restart continues it), and the
    exception is raised after that. Ctrl-C does the same and raises KeyboardInterrupt.
    quiet: no log lines from the run. The GIL is released while the solver runs.
    """
    config = deck(source, sets)
    if out is not None:
        config.output_dir = os.fspath(out)
    return _execute(config, threads, progress, quiet, restart=False, interval=progress_interval)


def restart(run_dir, sets=None, threads=0, progress=True, quiet=False, end_time=None, progress_interval=0.2):
    """Continues a run from the checkpoint in its folder, as `kessler run --restart DIR` does.

    Only the end time, the step limit, the checks and the output and checkpoint intervals may
    change: end_time="20 us" or sets={"solver.end_time": "20 us"}.
    """
    overrides = _overrides(sets)
    if end_time is not None:
        overrides.append(f"solver.end_time={end_time if isinstance(end_time, str) else repr(float(end_time))}")
    config = _kessler.restart_deck(os.fspath(run_dir), overrides)
    return _execute(config, threads, progress, quiet, restart=True, interval=progress_interval)


def verify(names=None, method="otm", progress=True):
    """Runs built-in verification problems (all of them when names is None; `kessler verify --list`
    names them) with a method, and returns one dict per problem: name, quantity, measured,
    reference, error, error_kind, tolerance, passed, seconds, note."""
    if isinstance(names, str):
        names = [names]

    def show(text):
        o = json.loads(text)
        print(f"{o['name']:<20} {o['measured']:>13.6g} {o['reference']:>13.6g} {o['error']:>10.3g} "
              f"{o['tolerance']:>9.3g}  {'pass' if o['passed'] else 'FAIL'} {o['quantity']} [{o['seconds']:.1f} s]",
              flush=True)

    texts = _kessler.verify(list(names or []), method, show if progress else None)
    return [json.loads(t) for t in texts]


def bench(names=None, size="small", threads=0, steps=0, sets=None):
    """Runs `kessler bench` (docs/performance.md): each problem (hvi-100k, hvi-1m, pysph-impact3d;
    all by default) in a fresh process of the kessler program, at size "tiny", "small" or "full".
    Returns its JSON as a dict: per problem the points, steps, us_per_point_step, peak memory per point
    and the time of each phase. Time it against something else in the same session only: machines
    are noisy."""
    if isinstance(names, str):
        names = [names]
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "bench.json")
        args = [_kessler.program(), "bench", *(names or []), "--size", size, "--json", out]
        if threads:
            args += ["--threads", str(threads)]
        if steps:
            args += ["--steps", str(steps)]
        for setting in _overrides(sets):
            args += ["--set", setting]
        done = subprocess.run(args, capture_output=True, text=True)
        if done.returncode != 0 and not os.path.exists(out):
            message = (done.stderr or done.stdout).strip().splitlines()
            raise _kessler.InputError(message[-1] if message else f"kessler bench failed ({done.returncode})")
        with open(out) as f:
            return json.load(f)
