# What the headless Blender tests share: checks that print and count, and an exit status Blender passes on
# (`--python-exit-code 1`: an exception fails the run too).
import sys
import traceback

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def run_checks(run, label):
    """Runs `run`, counting an exception as a failure, and exits 1 unless every check held."""
    try:
        run()
    except Exception:
        traceback.print_exc()
        failures.append("an exception")
    print(f"{label}: {len(failures)} failure(s)")
    sys.exit(1 if failures else 0)
