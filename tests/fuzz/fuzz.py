#!/usr/bin/env python3
"""The fuzz harness's two drivers (tests/fuzz/README.md).

  fuzz.py inprocess --driver build/bin/fuzzInProcess --root <source tree> --out <dir> --budget 30
      Replays tests/fuzz/fixtures/inProcess/ (each must end in a clean error), then runs the
      AddressSanitizer driver for the budget. When it dies on an input (sanitizer report, signal,
      hang, other exception), the input is kept, the failure printed with the command that
      reproduces it, and the driver resumes at the next iteration until the budget is spent.

  fuzz.py processes --bin build/bin --root <source tree> --out <dir> --budget 30
      Runs the real solvers (particleFlight on tests/fuzz/cases/freeFall, impactSph on
      tests/fuzz/cases/sodShockTube): a first good run gives the earlier results; then each
      iteration mutates one input of the case (a dictionary, the latest time's state or
      particles.vtp, particles.pvd; its content, or the file itself: missing, empty, a directory,
      a FIFO, a link to /dev/zero) and restarts the solver under a time and memory limit. The
      exit status must be 0 or 1 (never a signal, never the timeout), a status 1 must come with
      an error message and no "Error (internal)", and after a failed run every earlier file of
      the case must be byte-identical (sha256 before and after). A run that succeeds may add
      results; it must not name a time directory nan or inf. The case is restored after every
      run, so each iteration is independent: "--seed S --start I --iterations 1" repeats one.
      Fixtures: tests/fuzz/fixtures/processes/<name>/ (fixture.txt and input), replayed first.

The seed is --seed, else $MFDYN_FUZZ_SEED, else 14; it is printed. Exit status 0: no failure.
"""
import argparse
import hashlib
import os
import random
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

DEFAULT_SEED = 14


def seed_of(args):
    if args.seed is not None:
        return args.seed
    env = os.environ.get("MFDYN_FUZZ_SEED", "").strip()
    return int(env) if env else DEFAULT_SEED


def tail(text, lines=60):
    return "\n".join(text.splitlines()[-lines:])


# --------------------------------------------------------------------------------------------
# In process: supervise the AddressSanitizer driver.

ASAN_OPTIONS = ":".join([
    "detect_leaks=1",
    "handle_abort=1",  # an assert() or std::terminate is reported like a segfault
    "allocator_may_return_null=0",  # an absurd allocation is a report, not a std::bad_alloc
    "max_allocation_size_mb=1024",  # no reader needs a gigabyte for a test input
    "hard_rss_limit_mb=2048",  # the memory limit (RLIMIT_AS would stop ASan's shadow memory)
    "detect_stack_use_after_return=0",
    "print_summary=1",
])
UBSAN_OPTIONS = "print_stacktrace=1:halt_on_error=1"


def inprocess(args):
    seed = seed_of(args)
    out = Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    env = dict(os.environ)
    env["ASAN_OPTIONS"] = ASAN_OPTIONS + (":" + env["ASAN_OPTIONS"] if env.get("ASAN_OPTIONS") else "")
    env["UBSAN_OPTIONS"] = UBSAN_OPTIONS
    env.setdefault("OMP_NUM_THREADS", "1")
    base = [args.driver, "--root", args.root, "--out", str(out), "--input-timeout", str(args.input_timeout)]
    if args.kinds:
        base += ["--kinds", args.kinds]
    failures = []

    fixtures = sorted(p for p in (Path(args.root) / "tests/fuzz/fixtures/inProcess").glob("*")
                      if p.suffix in (".dict", ".vtp", ".pvd", ".state"))
    if fixtures:
        r = subprocess.run(base + ["--replay", "--expect-error"] + [str(p) for p in fixtures],
                           env=env, capture_output=True, text=True, errors="replace",
                           timeout=args.input_timeout * len(fixtures) + 60)
        print(f"fuzz.inProcess: replayed {len(fixtures)} fixtures (each must end in a clean error):")
        print(r.stdout, end="")
        if r.returncode != 0:
            print(tail(r.stderr), file=sys.stderr)
            failures.append(f"fixture replay ended with status {r.returncode}")

    print(f"fuzz.inProcess: seed {seed} (set MFDYN_FUZZ_SEED to change it), budget {args.budget} s", flush=True)
    begin = time.monotonic()
    start, inputs = args.start, 0
    while len(failures) < args.max_failures:
        left = args.budget - (time.monotonic() - begin)
        if left <= 0:
            break
        cmd = base + ["--seed", str(seed), "--start", str(start), "--budget", f"{left:.1f}"]
        try:
            r = subprocess.run(cmd, env=env, capture_output=True, text=True, errors="replace",
                               timeout=left + args.input_timeout + 60)
        except subprocess.TimeoutExpired as e:
            failures.append(f"the driver ran past its budget and watchdog (from iteration {start})")
            print(tail((e.stderr or b"").decode(errors="replace")), file=sys.stderr)
            break
        print(r.stdout, end="", flush=True)
        done = re.search(r"(\d+) inputs in [0-9.e+-]+ s", r.stdout)
        if done:
            inputs += int(done.group(1))
        if r.returncode == 0 and done:
            break
        m = re.search(r"FUZZ FAILED AT ITERATION (\d+)", r.stderr)
        print(tail(r.stderr, 80), file=sys.stderr, flush=True)
        if not m:
            # Not an input's failure: a leak report at exit, or the driver itself broken.
            failures.append(f"the driver ended with status {r.returncode} outside an input (see above)")
            break
        iteration = int(m.group(1))
        failures.append(f"iteration {iteration}: status {r.returncode}, "
                        + first_failure_line(r.stderr))
        inputs += iteration - start + 1 if not done else 0
        start = iteration + 1
    elapsed = time.monotonic() - begin
    print(f"fuzz.inProcess: {inputs} inputs in {elapsed:.1f} s ({inputs / max(elapsed, 1e-9):.0f} per second), "
          f"seed {seed}, {len(failures)} failures")
    for f in failures:
        print("  FAIL " + f)
    if failures:
        print(f"Failing inputs are in {out}. Keep one as a fixture: copy it to tests/fuzz/fixtures/inProcess/ "
              "(README.md).")
    return 1 if failures else 0


def first_failure_line(stderr):
    for pattern in (r"ERROR: AddressSanitizer: [^\n]*", r"AddressSanitizer: hard rss limit[^\n]*",
                    r"runtime error: [^\n]*", r"ERROR: LeakSanitizer: [^\n]*", r"FUZZ FAILURE: [^\n]*"):
        m = re.search(pattern, stderr)
        if m:
            return m.group(0)
    return "no sanitizer line"


# --------------------------------------------------------------------------------------------
# Processes: mutate a real case's inputs, run the solver, check the earlier results.

EXTREME_NUMBERS = ["0", "-1", "1", "-0", "nan", "inf", "-inf", "1e999", "-1e999", "5e-321", "1e-300",
                   "2147483648", "9223372036854775808", "18446744073709551615", "2305843009213693952",
                   "4e8", "1e30", "0x1p+1023", "3.5", "", "1 2", "\"nan\"", "\"0x1p+1024\"", "1e-12", "1e12"]

CASES = {
    # name: (solver, first end time, continued end time)
    "freeFall": ("particleFlight", "0.5", "0.52"),
    "sodShockTube": ("impactSph", "0.001", "0.0012"),
}

NUMBER = re.compile(rb"-?[0-9][0-9A-Za-z.+-]*")


def replace_number(data, rng, limit=None):
    limit = len(data) if limit is None else limit
    spans = [m.span() for m in NUMBER.finditer(data, 0, limit)]
    if not spans:
        return data
    a, b = rng.choice(spans)
    return data[:a] + rng.choice(EXTREME_NUMBERS).encode() + data[b:]


def generic_edit(data, rng, alphabet, limit=None):
    limit = len(data) if limit is None else min(limit, len(data))
    at = rng.randint(0, limit)
    op = rng.randrange(7)
    if op == 0:
        return data[:at] + data[at + rng.randint(1, 8):]
    if op in (1, 2):
        return data[:at] + bytes([rng.choice(alphabet)]) + data[at:]
    if op == 3:
        return data[:at] + data[at:at + rng.randint(1, 32)] + data[at:]
    if op == 4:
        return data[:at]
    if op == 5:
        return data[:at] + bytes([rng.randrange(256)]) + data[at:]
    if at < len(data):
        return data[:at] + bytes([data[at] ^ (1 << rng.randrange(8))]) + data[at + 1:]
    return data


def repeat_span(data, rng, units, limit=None):
    limit = len(data) if limit is None else min(limit, len(data))
    at = rng.randint(0, limit)
    count = rng.randint(20000, 120000) if rng.randrange(4) == 0 else rng.randint(1, 300)
    return data[:at] + rng.choice(units) * count + data[at:]


def mutate_dictionary(data, rng, is_state):
    for _ in range(rng.randint(1, 4)):
        op = rng.randrange(10)
        if op < 4:
            data = generic_edit(data, rng, b"{}();$#\"/*\\\n e.-+[]")
        elif op < 7 or is_state:
            data = replace_number(data, rng)
        elif op == 7:
            data = repeat_span(data, rng, [b"{", b"a {", b"(", b"x 1;"])
        elif op == 8:
            target = rng.choice(["missing", ".", "/dev/null", "/dev/zero", "../../../../etc/passwd",
                                 "controlDict"])
            directive = rng.choice([b"#include", b"#includeEtc"])
            at = rng.randint(0, len(data))
            data = data[:at] + b"\n" + directive + b" \"" + target.encode() + b"\"\n" + data[at:]
        else:
            levels = rng.randint(1, 48)
            chain = b"\nm0 1;\n" + b"".join(b"m%d ($m%d $m%d);\n" % (k, k - 1, k - 1) for k in range(1, levels + 1))
            data += chain
    return data


SIZE_ATTRIBUTE = re.compile(rb'(?:NumberOf\w+|offset|header_type)="([^"]*)"')


def mutate_xml(data, rng, binary_tail):
    def header_end():
        tag = data.find(b"<AppendedData") if binary_tail else -1
        underscore = data.find(b"_", tag) if tag >= 0 else -1
        return underscore + 1 if underscore >= 0 else len(data)

    for _ in range(rng.randint(1, 3)):
        header = header_end()
        op = rng.randrange(7)
        if op < 2:
            data = generic_edit(data, rng, b"<>/=\"'&;#?! \n_x", header)
        elif op == 2:
            data = replace_number(data, rng, header)
        elif op == 3:  # a size the reader multiplies, allocates or seeks by, set to an extreme
            spans = [m.span(1) for m in SIZE_ATTRIBUTE.finditer(data, 0, header)]
            if spans:
                a, b = rng.choice(spans)
                data = data[:a] + rng.choice(EXTREME_NUMBERS).encode() + data[b:]
        elif op == 4:
            data = repeat_span(data, rng, [b"<a>", b"<!-- c -->", b"&amp;"], header)
        elif binary_tail and len(data) > header + 8:
            at = rng.randint(header, len(data) - 8)
            word = rng.choice([0, 1, 2**64 - 1, 2**63, 2**61, 2**32, 4 * 10**8, 0x7ff8000000000000])
            data = data[:at] + word.to_bytes(8, "little") + data[at + 8:]
        else:
            data = generic_edit(data, rng, b"<>/=\"'&;#?! \n_x", header)
    return data


SPECIALS = ["missing", "empty", "directory", "fifo", "devzero", "selflink"]


def hash_tree(root):
    """sha256 of every file under root, by relative path (links and FIFOs by what they are)."""
    hashes = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in filenames + [d for d in dirnames if os.path.islink(os.path.join(dirpath, d))]:
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            st = os.lstat(path)
            if stat.S_ISREG(st.st_mode):
                h = hashlib.sha256()
                with open(path, "rb") as f:
                    for block in iter(lambda: f.read(1 << 20), b""):
                        h.update(block)
                hashes[rel] = h.hexdigest()
            else:
                hashes[rel] = "mode %o" % stat.S_IFMT(st.st_mode)
    return hashes


def latest_time(case):
    times = []
    for p in case.iterdir():
        try:
            times.append((float(p.name), p.name))
        except ValueError:
            pass
    return max(times)[1]


def set_end_time(controldict, value):
    text = controldict.read_text()
    text, n = re.subn(r"(?m)^endTime\s+[^;]*;", f"endTime         {value};", text)
    if n != 1:
        raise SystemExit(f"fuzz.py: cannot set endTime in {controldict}")
    controldict.write_text(text)


def build_stamp(bindir):
    """(name, size, mtime) of the programs and libraries of the build, to notice a rebuild."""
    stamp = []
    for d in (Path(bindir), Path(bindir).parent / "lib"):
        if d.is_dir():
            for p in sorted(d.iterdir()):
                try:
                    st = p.stat()
                    stamp.append((p.name, st.st_size, st.st_mtime_ns))
                except OSError:
                    stamp.append((p.name, -1, -1))
    return stamp


def build_changing(bindir, before):
    """Whether the build changed since `before`; if so, returns once it has been still for 10 s."""
    if build_stamp(bindir) == before:
        return False
    print("fuzz.processes: the build changed under the run; waiting for it to settle", flush=True)
    last, still = build_stamp(bindir), 0
    while still < 10:
        time.sleep(2)
        now = build_stamp(bindir)
        still = still + 2 if now == last else 0
        last = now
    return True


def limits(memory_mb):
    def apply():
        os.setsid()
        resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        resource.setrlimit(resource.RLIMIT_FSIZE, (512 << 20, 512 << 20))
    return apply


def run_limited(cmd, timeout, memory_mb, env, grace=10):
    """(status, output, how): how is "finished", "stopped" (still running at the timeout, then
    ended within `grace` seconds of SIGTERM) or "hung" (killed: SIGTERM did not end it)."""
    p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         env=env, preexec_fn=limits(memory_mb))
    try:
        out, _ = p.communicate(timeout=timeout)
        return p.returncode, out.decode(errors="replace"), "finished"
    except subprocess.TimeoutExpired:
        pass
    # A run still stepping is stopped the way a user stops it; one that does not answer is hung.
    p.send_signal(signal.SIGTERM)
    try:
        out, _ = p.communicate(timeout=grace)
        return p.returncode, out.decode(errors="replace"), "stopped"
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate()
        return None, out.decode(errors="replace"), "hung"


class Case:
    def __init__(self, name, root, bindir, work, env, args):
        self.name = name
        self.solver, first_end, self.end = CASES[name]
        self.bindir, self.env, self.args = Path(bindir), env, args
        self.pristine = work / f"{name}.pristine"
        self.case = work / name
        shutil.copytree(Path(root) / "tests/fuzz/cases" / name, self.pristine)
        for tool in ("particleGen", self.solver):
            status, out, _ = run_limited([str(self.bindir / tool), "-case", str(self.pristine)], 120, 4096, env)
            if status != 0:
                raise SystemExit(f"fuzz.py: the first good run of {name} failed ({tool}, status {status}):\n"
                                 + tail(out))
        # The mutated runs continue from the first run's last write.
        set_end_time(self.pristine / "system/controlDict", self.end)
        self.latest = latest_time(self.pristine)
        self.hashes = hash_tree(self.pristine)
        self.targets = (sorted(f"constant/{p.name}" for p in (self.pristine / "constant").iterdir())
                        + ["system/controlDict", f"{self.latest}/state", f"{self.latest}/particles.vtp",
                           "particles.pvd"])

    def restore(self):
        if self.case.exists() or self.case.is_symlink():
            shutil.rmtree(self.case)
        shutil.copytree(self.pristine, self.case, symlinks=True)

    def mutation(self, rng):
        """(target, kind, bytes): kind 'content' or one of SPECIALS."""
        target = rng.choice(self.targets)
        if rng.randrange(12) == 0:
            return target, rng.choice(SPECIALS), b""
        data = (self.pristine / target).read_bytes()
        if target.endswith(".vtp"):
            data = mutate_xml(data, rng, True)
        elif target.endswith(".pvd"):
            data = mutate_xml(data, rng, False)
        else:
            data = mutate_dictionary(data, rng, target.endswith("state"))
        return target, "content", data

    def apply(self, target, kind, data):
        path = self.case / target
        if path.exists() or path.is_symlink():
            path.unlink()
        if kind == "content":
            path.write_bytes(data)
        elif kind == "empty":
            path.write_bytes(b"")
        elif kind == "directory":
            path.mkdir()
        elif kind == "fifo":
            os.mkfifo(path)
        elif kind == "devzero":
            path.symlink_to("/dev/zero")
        elif kind == "selflink":
            path.symlink_to(path.name)
        elif kind != "missing":
            raise SystemExit(f"fuzz.py: unknown mutation kind {kind}")

    def run(self, target, kind, data):
        """The failure found, or None."""
        for attempt in range(3):
            self.restore()
            self.apply(target, kind, data)
            built = build_stamp(self.bindir)
            status, out, how = run_limited([str(self.bindir / self.solver), "-case", str(self.case)],
                                           self.args.run_timeout, self.args.memory_mb, self.env)
            # A solver or library rebuilt while the harness runs (a developer's tree) is not the
            # input's doing (a half-written library crashes on loading): wait for the build to
            # settle and run again.
            if status in (0, 1):
                break
            if "error while loading shared libraries" in out:  # written before this run began
                build_changing(self.bindir, [])
            elif not build_changing(self.bindir, built):
                break
        problem = self.judge(target, status, out, how)
        return problem, ("stopped" if how == "stopped" and problem is None else status), out

    def extended(self, rel):
        """Whether case/rel holds pristine/rel's content with results added after it."""
        before, after = (self.pristine / rel).read_bytes(), (self.case / rel).read_bytes()
        if rel == "particles.pvd":
            return set(PVD_ENTRY.findall(before)) <= set(PVD_ENTRY.findall(after))
        return rel.endswith(".csv") and after.startswith(before)

    def judge(self, target, status, out, how):
        if how == "hung":
            return (f"hang: still running after {self.args.run_timeout} s, and SIGTERM did not stop it "
                    "(killed)")
        in_loop = "Starting time loop" in out
        if how == "stopped":
            # A long run the input asked for (a huge endTime, a tiny step): it must have been in
            # its time loop, stop cleanly on SIGTERM (status 143, or 0 before issue 14) and keep
            # every earlier result; start-up taking that long on this case is a hang.
            if not in_loop:
                return (f"hang in start-up: no time loop after {self.args.run_timeout} s "
                        f"(SIGTERM gave status {status})")
            if status not in (0, 143):
                return f"a run stopped by SIGTERM ended with status {status} (expected 143)"
        elif status < 0:
            return f"killed by signal {-status} ({signal.Signals(-status).name})"
        elif status not in (0, 1):
            return f"exit status {status} (expected 0 or 1)"
        if "Error (internal)" in out:
            return "an internal error reached the user: " + line_with(out, "Error (internal)")
        if status == 0 or how == "stopped":
            for p in self.case.iterdir():
                if p.name.lower().lstrip("+-") in ("nan", "inf", "infinity"):
                    return f"exit {status} but wrote a time directory named '{p.name}'"
            if how == "finished":
                return None
        elif "Error" not in out:
            return "exit status 1 without an error message"
        after = hash_tree(self.case)
        # A run that failed in its time loop (a blow-up the mutated input caused) may have added
        # results before it stopped: the failing state's directory, its entry in particles.pvd,
        # rows appended to the CSVs. Earlier results must still be there unchanged: earlier
        # entries of particles.pvd all listed, each CSV's earlier content its first bytes. A run
        # that failed before its time loop (bad input) must have changed nothing at all.
        changed = [rel for rel, h in self.hashes.items()
                   if rel != target and not rel.startswith(target + "/") and after.get(rel) != h
                   and not (in_loop and rel in after and self.extended(rel))]
        if changed:
            return (f"{'stopped' if how == 'stopped' else 'exit 1'}, but earlier results changed: "
                    + ", ".join(f"{rel} ({'removed' if rel not in after else 'modified'})" for rel in changed[:8])
                    + (f" and {len(changed) - 8} more" if len(changed) > 8 else ""))
        return None


PVD_ENTRY = re.compile(rb'<DataSet\s+timestep="([^"]*)"[^>]*\sfile="([^"]*)"')


def line_with(text, needle):
    for line in text.splitlines():
        if needle in line:
            return line.strip()[:300]
    return ""


def read_fixture(d):
    meta = dict(line.split(None, 1) for line in (d / "fixture.txt").read_text().splitlines()
                if line.strip() and not line.startswith("#"))
    data = (d / "input").read_bytes() if (d / "input").exists() else b""
    return meta["case"].strip(), meta["target"].strip(), meta["kind"].strip(), data


def keep_failure(out, case, target, kind, data, seed, iteration, problem):
    d = out / "failures" / f"{case}-seed{seed}-iter{iteration}"
    d.mkdir(parents=True, exist_ok=True)
    (d / "fixture.txt").write_text(f"# {problem}\ncase {case}\ntarget {target}\nkind {kind}\n")
    if kind == "content":
        (d / "input").write_bytes(data)
    return d


def processes(args):
    seed = seed_of(args)
    out = Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    work = out / "work"
    work.mkdir(parents=True)
    env = dict(os.environ)
    env["OMP_NUM_THREADS"] = "1"
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    cases = {name: Case(name, args.root, args.bin, work, env, args) for name in CASES}
    failures = []
    me = f"{sys.executable} {os.path.abspath(__file__)} processes --bin {args.bin} --root {args.root} --out {out}"

    def report(label, case, target, kind, status, problem, output, kept):
        failures.append(f"{label} {case.name}: {kind} {target}: {problem}")
        print(f"\nFUZZ FAILURE ({label}, {case.name}, {kind} {target}): {problem}\n"
              f"  solver output (last lines):\n{tail(output, 15)}\n  input kept in {kept}", flush=True)

    fixtures = sorted(d for d in (Path(args.root) / "tests/fuzz/fixtures/processes").glob("*") if d.is_dir())
    for d in fixtures:
        name, target, kind, data = read_fixture(d)
        case = cases[name]
        problem, status, output = case.run(target, kind, data)
        if problem is None and status != 1:
            problem = f"a fixture must end in a clean error (exit 1), it exited {status}"
        if problem:
            report("fixture", case, target, kind, status, problem, output, d)
        else:
            print(f"fuzz.processes: fixture {d.name}: {line_with(output, 'Error')[:160]}")

    print(f"fuzz.processes: seed {seed} (set MFDYN_FUZZ_SEED to change it), budget {args.budget} s", flush=True)
    begin = time.monotonic()
    names = sorted(cases)
    counts = {name: [0, 0, 0] for name in names}  # exit 0, exit 1, long runs stopped by SIGTERM
    iteration = args.start
    while len(failures) < args.max_failures:
        if args.iterations is not None:
            if iteration - args.start >= args.iterations:
                break
        elif time.monotonic() - begin >= args.budget:
            break
        rng = random.Random(f"{seed}:{iteration}")
        case = cases[names[rng.randrange(len(names))]]
        target, kind, data = case.mutation(rng)
        problem, status, output = case.run(target, kind, data)
        if status in (0, 1):
            counts[case.name][status] += 1
        elif status == "stopped":
            counts[case.name][2] += 1
        if problem:
            kept = keep_failure(out, case.name, target, kind, data, seed, iteration, problem)
            report(f"iteration {iteration}", case, target, kind, status, problem, output, kept)
            print(f"  reproduce: {me} --seed {seed} --start {iteration} --iterations 1", flush=True)
        elif args.verbose:
            print(f"  {iteration} {case.name} {kind} {target}: exit {status} {line_with(output, 'Error')[:120]}")
        iteration += 1
    elapsed = time.monotonic() - begin
    runs = iteration - args.start
    summary = ", ".join(f"{n} {c[0]} ok/{c[1]} errors/{c[2]} long runs stopped" for n, c in counts.items())
    print(f"fuzz.processes: {runs} runs in {elapsed:.1f} s ({runs / max(elapsed, 1e-9):.1f} per second), "
          f"seed {seed}, iterations {args.start}..{iteration - 1}; {summary}; {len(failures)} failures")
    for f in failures:
        print("  FAIL " + f)
    if failures:
        print(f"Failing inputs are in {out / 'failures'}. Keep one as a fixture: copy its directory to "
              "tests/fuzz/fixtures/processes/ (README.md).")
    for case in cases.values():
        shutil.rmtree(case.case, ignore_errors=True)
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="mode", required=True)
    for mode in ("inprocess", "processes"):
        p = sub.add_parser(mode)
        p.add_argument("--root", required=True, help="the source tree")
        p.add_argument("--out", required=True, help="scratch and failure directory (emptied first)")
        p.add_argument("--budget", type=float, default=30, help="seconds of fuzzing (after the fixtures)")
        p.add_argument("--seed", type=int, default=None)
        p.add_argument("--start", type=int, default=0, help="first iteration")
        p.add_argument("--max-failures", type=int, default=20, help="stop after this many")
        if mode == "inprocess":
            p.add_argument("--driver", required=True)
            p.add_argument("--input-timeout", type=int, default=20, help="seconds per input (a hang)")
            p.add_argument("--kinds", default=None, help="of dict,vtp,pvd,state (default all)")
        else:
            p.add_argument("--bin", required=True, help="directory of particleGen and the solvers")
            p.add_argument("--iterations", type=int, default=None, help="this many runs instead of a budget")
            p.add_argument("--run-timeout", type=int, default=5, help="seconds per solver run (a hang)")
            p.add_argument("--memory-mb", type=int, default=4096, help="address-space limit per run")
            p.add_argument("--verbose", action="store_true", help="print every run's outcome")
    args = parser.parse_args()
    return inprocess(args) if args.mode == "inprocess" else processes(args)


if __name__ == "__main__":
    sys.exit(main())
