"""What every case-test script shares: one PASS/FAIL line per check, and the exit code (1 if any
check failed, or if no check ran at all: a script whose mode or branch ran nothing has verified
nothing, and must not pass). Usage: `from case_checks import check, finish` ... `finish()`;
`unknown_mode(mode, modes)` ends a mode dispatcher's chain; `readme_figure(value, "2.87", what)`
asserts a figure the README prints to 3 units of its last digit."""
import sys

failures = []
checks_run = [0]


def check(ok, text):
    checks_run[0] += 1
    print(("PASS " if ok else "FAIL ") + text)
    if not ok:
        failures.append(text)
    return ok


def last_digit(text):
    """The unit of the last digit of a figure as printed ("2.87" -> 0.01, "1.2e-6" -> 1e-7, "12" -> 1)."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** (-decimals + (int(exponent) if exponent else 0))


def readme_figure(value, text, what, scale=1.0):
    """Checks that value (times scale, e.g. 100 for percent) is the README's figure `text` to 3 units of
    its last printed digit (issue 34)."""
    figure, tolerance = float(text), 3 * last_digit(text)
    return check(abs(value * scale - figure) <= tolerance * (1 + 1e-9),
                 "%s: %.6g is the README's %s (+- %.2g)" % (what, value * scale, text, tolerance))


def unknown_mode(mode, modes):
    sys.exit("FAIL unknown mode %r (expected one of %s)" % (mode, ", ".join(modes)))


def finish():
    if checks_run[0] == 0:
        print("FAIL no check ran")
        sys.exit(1)
    print("%d check(s) failed" % len(failures) if failures else "all %d checks passed" % checks_run[0])
    sys.exit(1 if failures else 0)
