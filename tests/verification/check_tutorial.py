"""docs/tutorial.md stays true: its deck is the one it runs, `kessler check` prints what it shows (the
deck and the mistake), and the deck runs (shortened here) to a hole in the plate, read back with the
Python calls it shows.

    python3 check_tutorial.py KESSLER TUTORIAL.md WORK_DIR
"""

import os
import re
import subprocess
import sys


def blocks(text, language):
    """The contents of the fenced blocks of a language ("" for plain ones), in order."""
    found, current, kind = [], None, None
    for line in text.splitlines(keepends=True):
        if line.startswith("```"):
            if current is None:
                current, kind = [], line[3:].strip()
            else:
                if kind == language:
                    found.append("".join(current))
                current = None
        elif current is not None:
            current.append(line)
    return found


def run(args, cwd):
    done = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


def main(kessler, tutorial, work):
    text = open(tutorial, encoding="utf-8").read()
    os.makedirs(work, exist_ok=True)
    [deck] = [b for b in blocks(text, "yaml") if b.startswith("title:")]
    with open(os.path.join(work, "my-shield.yaml"), "w") as f:
        f.write(deck)

    # `kessler check` prints what the tutorial shows.
    code, out = run([kessler, "check", "my-shield.yaml"], work)
    shown = [b for b in blocks(text, "") if b.startswith("my-shield.yaml: ok")]
    assert code == 0 and shown and out.strip() == shown[0].strip(), (out, shown)

    # The mistake it shows, with the message it shows.
    mistake = re.search(r"With `velocity: \[0, 0, (-6.5 km)\]`", text)
    assert mistake, "the tutorial's mistake is not where this test looks"
    with open(os.path.join(work, "my-shield.yaml"), "w") as f:
        f.write(deck.replace("-6.5 km/s", mistake.group(1)))
    code, out = run([kessler, "check", "my-shield.yaml"], work)
    expected = [b for b in blocks(text, "") if b.startswith("kessler: error:")]
    assert code == 1 and expected and out.strip() == expected[0].strip(), (out, expected)

    # The deck runs (1.5 us here: the sphere is through the plate) and Python reads it as shown.
    with open(os.path.join(work, "my-shield.yaml"), "w") as f:
        f.write(deck)
    code, out = run([kessler, "run", "my-shield.yaml", "--quiet", "--set", "solver.end_time=1.5 us",
                     "--set", "analysis.plots=false"], work)
    assert code == 0, out
    import kessler as k
    r = k.Results(os.path.join(work, "results", "my-shield"))
    assert r.status == "completed" and r.analysis["holes"][0]["found"], r.analysis["holes"]
    last = r.points(-1)
    assert last["temperature"].max() > 300.0 and last["position"].shape[1] == 3
    assert len(r.fragments) >= 1 and len(r.history["total_J"]) == len(r.times)
    print("tutorial ok: deck checks as shown, the mistake reads as shown, the run holes the plate "
          f"({1e3 * r.analysis['holes'][0]['diameter_m']:.1f} mm at 1.5 us)")


if __name__ == "__main__":
    main(*sys.argv[1:4])
