"""What every case-test script shares: one PASS/FAIL line per check, and the exit code (1 if any
check failed). Usage: `from case_checks import check, finish` ... `finish()`."""
import sys

failures = []


def check(ok, text):
    print(("PASS " if ok else "FAIL ") + text)
    if not ok:
        failures.append(text)
    return ok


def finish():
    print("%d check(s) failed" % len(failures) if failures else "all checks passed")
    sys.exit(1 if failures else 0)
