"""What the scripts read from a run's expanded parameters.prm."""
import os
import re


def constraint_tolerances(directory):
    """{"f_1": Tolerance, ...} of the run in @p directory (its
    parameters.prm); {} if there is none."""
    path = os.path.join(directory, "parameters.prm")
    if not os.path.exists(path):
        return {}
    tolerances, section = {}, None
    for line in open(path):
        line = line.split("#")[0].strip()
        m = re.match(r"subsection Constraint (\d+)$", line)
        if m:
            section = "f_" + m.group(1)
        elif line == "end":
            section = None
        elif section:
            m = re.match(r"set Tolerance\s*=\s*(\S+)", line)
            if m:
                tolerances[section] = float(m.group(1))
    return tolerances


def relative_difference(name, value, reference, tolerances):
    """|value - reference| relative to the functional's quantity: |g| for
    an objective, |Q| = |f + Tolerance| for a constraint f = Q - Tolerance
    (an active constraint is near 0, its quantity is not), as softopt's
    branch check and verification measure it."""
    scale = abs(reference + tolerances.get(name, 0.0))
    return abs(value - reference) / max(scale, 1e-12)
