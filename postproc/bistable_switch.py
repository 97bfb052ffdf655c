#!/usr/bin/python3
"""What a bistable switch's force-displacement curve says: switching forces, positions, energy barrier.

analyse(rows, force_of, stroke_of) takes the rows of a nonlinear run's curve.csv, a function giving
the force of a row and one giving the stroke (displacement along the push, positive), and returns
  force_top      the largest force before the snap (the first maximum of the curve)
  force_bottom   the pull-back force, the magnitude of the minimum after it (0 if it stays positive:
                 the switch is not bistable and springs back)
  stroke_middle  the unstable equilibrium between them (force zero, falling)
  stroke_second  the second stable position (force zero again, rising); None if not reached
  barrier        the energy to push from the first stable position over the middle one
  return_barrier the energy from the second stable position back over the middle one
Zero crossings are interpolated linearly between steps; energies are trapezoidal sums.
"""


def zero_crossing(s0, f0, s1, f1):
    return s0 + (s1 - s0) * f0 / (f0 - f1)


def analyse(rows, force_of, stroke_of):
    stroke = [0.0] + [stroke_of(r) for r in rows]
    force = [0.0] + [force_of(r) for r in rows]
    top = next((i for i in range(1, len(force) - 1) if force[i] >= force[i - 1] and force[i] > force[i + 1]), None)
    result = {"force_top": max(force), "force_bottom": 0.0, "stroke_middle": None, "stroke_second": None,
              "barrier": None, "return_barrier": None}
    if top is None:
        return result
    result["force_top"] = force[top]
    falling = next((i for i in range(top + 1, len(force)) if force[i] <= 0 < force[i - 1]), None)
    if falling is None:
        return result
    result["stroke_middle"] = zero_crossing(stroke[falling - 1], force[falling - 1], stroke[falling], force[falling])
    rising = next((i for i in range(falling + 1, len(force)) if force[i] >= 0 > force[i - 1]), None)
    end = rising if rising is not None else len(force)
    result["force_bottom"] = -min(force[falling:end])

    def work(a, b):
        """Trapezoidal work of the force from stroke a to stroke b (a < b, within the steps)."""
        total = 0.0
        for i in range(1, len(stroke)):
            lo, hi = max(stroke[i - 1], a), min(stroke[i], b)
            if hi <= lo or stroke[i] == stroke[i - 1]:
                continue
            at = lambda s: force[i - 1] + (force[i] - force[i - 1]) * (s - stroke[i - 1]) / (stroke[i] - stroke[i - 1])
            total += 0.5 * (at(lo) + at(hi)) * (hi - lo)
        return total

    result["barrier"] = work(0.0, result["stroke_middle"])
    if rising is not None:
        result["stroke_second"] = zero_crossing(stroke[rising - 1], force[rising - 1], stroke[rising], force[rising])
        result["return_barrier"] = -work(result["stroke_middle"], result["stroke_second"])
    return result
