#!/usr/bin/env python3
"""Compares the function objects' output of two runs of one case: every CSV under
postProcessing/ and the log's error lines (`    error <name>  <value> (exact <x>, relative <r>) at
CPU <s> s, step <n>, t = <t>`), value by value.

    compareRuns.py <reference case> <other case> <log name> <tolerance> [<file>:<column> ...]

Headers, row counts, words (errorNorms' field column) and error names must be equal; numbers
may differ by `tolerance` times their column's scale: the largest |value| of the column in the
reference, or of the file where a column is all round-off (a tube's total momentum, 1e-17, whose
scale is the momenta and energies beside it). Files and the summary print 10 significant digits
(CsvFile, SolverRun): two values that differ in the last bits may round apart there, by one unit
in the tenth digit, which is allowed as well and counted. Of runSummary.csv only the norms are
compared: its other columns are the run's cost and size, not a function object's. Each
<file>:<column> given (health.csv:hourglass) is left out too, for a reason the caller states. Prints the largest difference over its scale and where it is;
exits 1 at the first difference beyond both allowances, naming file, row, column and values.
"""
import math
import pathlib
import re
import sys

RUN_COLUMNS = {"wallTime", "steps", "particles", "threads", "particleStepsPerSecond"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def lastDigit(value):
    """One unit in the tenth significant digit of value as printed with %.10g."""
    if value == 0 or not math.isfinite(value):
        return 0.0
    return 10.0 ** (math.floor(math.log10(abs(value))) - 9)


class Comparison:
    def __init__(self, tolerance, skipped):
        self.tolerance = tolerance
        self.skipped = skipped
        self.largest = (0.0, "")  # largest |a - b| / scale, and where
        self.roundedApart = 0  # values one printed digit apart (within the allowance)
        self.values = 0

    def fail(self, message):
        print("FAIL: " + message)
        sys.exit(1)

    def numbers(self, a, b, scale, where):
        self.values += 1
        if math.isnan(a) and math.isnan(b):
            return
        if a == b:
            return
        difference = abs(a - b)
        relative = difference / scale if scale > 0 else math.inf
        if relative > self.largest[0]:
            self.largest = (relative, where)
        if relative <= self.tolerance:
            return
        if difference <= 1.000001 * max(lastDigit(a), lastDigit(b)):
            self.roundedApart += 1
            return
        self.fail(f"{where}: {a!r} against {b!r} (difference {difference:.3g}, {relative:.3g} of the scale {scale:.3g})")

    def csv(self, reference, other, name):
        rowsA = reference.read_text().splitlines()
        rowsB = other.read_text().splitlines()
        if not rowsA or rowsA[0] != rowsB[0]:
            self.fail(f"{name}: headers differ: {rowsA[:1]} against {rowsB[:1]}")
        if len(rowsA) != len(rowsB):
            self.fail(f"{name}: {len(rowsA) - 1} rows against {len(rowsB) - 1}")
        header = rowsA[0].split(",")
        cellsA = [r.split(",") for r in rowsA[1:]]
        cellsB = [r.split(",") for r in rowsB[1:]]
        values = [[number(c) for c in row] for row in cellsA]
        fileScale = max((abs(v) for row in values for v in row if v is not None and math.isfinite(v)), default=0.0)
        for c, column in enumerate(header):
            if name.endswith("runSummary.csv") and column in RUN_COLUMNS:
                continue
            if (pathlib.Path(name).name, column) in self.skipped:
                continue
            col = [row[c] for row in values if c < len(row) and row[c] is not None and math.isfinite(row[c])]
            scale = max((abs(v) for v in col), default=0.0)
            if scale < 1e-9 * fileScale:  # round-off: the file's scale
                scale = fileScale
            for k, (rowA, rowB) in enumerate(zip(cellsA, cellsB)):
                if len(rowA) != len(rowB):
                    self.fail(f"{name} row {k + 1}: {len(rowA)} cells against {len(rowB)}")
                a, b = number(rowA[c]), number(rowB[c])
                if a is None or b is None:
                    if rowA[c] != rowB[c]:
                        self.fail(f"{name} row {k + 1} {column}: '{rowA[c]}' against '{rowB[c]}'")
                    continue
                self.numbers(a, b, scale, f"{name} row {k + 1} {column}")

    def errorLines(self, reference, other):
        pattern = re.compile(r"^    error (\S+)  (\S+) \(exact (\S+), relative (\S+)\) at CPU \S+ s, step (\S+), t = (\S+)$")

        def lines(log):
            found = [pattern.match(l) for l in log.read_text().splitlines() if l.startswith("    error ")]
            if any(m is None for m in found):
                self.fail(f"{log}: an error line of another form")
            return found

        a, b = lines(reference), lines(other)
        if len(a) != len(b):
            self.fail(f"log: {len(a)} error lines against {len(b)}")
        if not a:
            self.fail(f"{reference}: no error lines")
        for la, lb in zip(a, b):
            name = la.group(1)
            if name != lb.group(1) or la.group(5) != lb.group(5) or la.group(6) != lb.group(6):
                self.fail(f"log: error line '{la.group(0).strip()}' against '{lb.group(0).strip()}'")
            for g, what in ((2, "value"), (3, "exact"), (4, "relative")):
                x, y = number(la.group(g)), number(lb.group(g))
                if x is None or y is None:
                    if la.group(g) != lb.group(g):
                        self.fail(f"log: error {name} {what}: {la.group(g)} against {lb.group(g)}")
                    continue
                self.numbers(x, y, abs(x), f"log error {name} {what}")
        return len(a)


def main():
    reference, other, logName, tolerance = (pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), sys.argv[3],
                                            float(sys.argv[4]))
    skipped = {tuple(s.split(":", 1)) for s in sys.argv[5:]}
    comparison = Comparison(tolerance, skipped)
    files = sorted(p.relative_to(reference) for p in (reference / "postProcessing").rglob("*.csv"))
    others = sorted(p.relative_to(other) for p in (other / "postProcessing").rglob("*.csv"))
    if files != others:
        comparison.fail(f"the CSV files differ: {[str(f) for f in files]} against {[str(f) for f in others]}")
    for f in files:
        comparison.csv(reference / f, other / f, str(f))
    errors = comparison.errorLines(reference / logName, other / logName)
    largest, where = comparison.largest
    print(f"{len(files)} files and {errors} error lines, {comparison.values} values: largest difference "
          f"{largest:.3g} of its scale ({where or 'none'}), {comparison.roundedApart} values one printed digit apart")


main()
