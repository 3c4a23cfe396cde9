#!/usr/bin/env python3
"""scripts/plot --over on made-up logs with the console's real headers (read from pc/core, so a
renamed column breaks this test, not a user's plot). Two flights give the same roll step at
different times; each log's time 0 must land on its own step (or mode change), in what the script
prints and in the data it hands gnuplot. Bad input fails with one line and the right status.
The telemetry plot's panels: height (where the QR marked it valid) and the lift set-point on the
engines' panel, read from the gnuplot script and data the plot keeps.
usage: plot_overlay_test.py align|errors|telemetry"""
import math
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = ROOT / "scripts/plot"
PERIOD_S = 0.01  # a telemetry log line every 10 ms


def header(source, function):
    """The column names a console function returns, in order."""
    text = (ROOT / source).read_text()
    return re.findall(r'"([^"]+)"', re.search(function + r"[^{]*\{\s*return \{(.*?)\};", text, re.S).group(1))


def write_log(path, columns, rows):
    """A CSV as qrterm writes it; a column a row leaves out is 0, one it sets to None an empty field."""
    fields = [[c for c in columns]] + [["" if r.get(c, 0) is None else str(r.get(c, 0)) for c in columns] for r in rows]
    path.write_text("".join(",".join(f) + "\r\n" for f in fields))


def flight(start_us, full_at, step_at, lines=600):
    """A QR telemetry log: safe, then full control at line full_at, a 0.1 rad roll step at step_at
    with the vehicle following it."""
    rows = []
    for i in range(lines):
        k = i - step_at
        rows.append({"line": i, "time_us": start_us + round(i * PERIOD_S * 1e6), "mode": 5 if i >= full_at else 0,
                     "roll_sp_1e-4rad": 1000 if k >= 0 else 0,
                     "phi_1e-4rad": 0 if k < 0 else round(1000 * (1 - math.exp(-k / 15))),
                     **{f"engine_{e}_0to1000": 400 if i >= full_at else 0 for e in ("front", "right", "back", "left")}})
    return rows


def plot(*args):
    return subprocess.run([sys.executable, str(TOOL), *map(str, args)], capture_output=True, text=True)


def expect(condition, message):
    if not condition:
        sys.exit(f"FAIL: {message}")
    print(f"ok: {message}")


def offsets(run):
    """Each log's time 0 as the script reports it, seconds from its first row."""
    return [float(s) for s in re.findall(r"at (\S+) s from its first row", run.stdout)]


def data(path, column):
    rows = [line.split() for line in path.read_text().splitlines()]
    return [(float(r[0]), float(r[column])) for r in rows]


def align(folder):
    log = header("pc/core/log_csv.cpp", r"log_header\(const wire::TelemetryLogRecord&\)")
    before, after = folder / "before.csv", folder / "after.csv"
    # The same flight, the second 2.5 s later in its log and on a clock that started elsewhere.
    write_log(before, log, flight(0, full_at=50, step_at=100))
    write_log(after, log, flight(7_000_000, full_at=300, step_at=350))

    keep = folder / "keep"
    keep.mkdir()
    run = plot(before, "--over", after, "--align", "step:roll_sp_1e-4rad", "--keep-data", keep,
               "--out", folder / "step.png")
    expect(run.returncode == 0, f"two telemetry logs overlaid on a roll step ({run.stderr.strip()})")
    expect((folder / "step.png").read_bytes()[:4] == b"\x89PNG", "the overlay is a PNG")
    found = offsets(run)
    expect(len(found) == 2 and abs(found[0] - 1.0) < 1e-9 and abs(found[1] - 3.5) < 1e-9,
           f"each step found where it was built: 1.0 s and 3.5 s ({run.stdout.strip()})")
    for n in (1, 2):
        setpoint = data(keep / f"log{n}" / "setpoint.dat", 1)
        first_up = next(t for t, roll in setpoint if roll > 0)
        expect(abs(first_up) < 1e-9, f"log {n}'s step is at time 0 in the data gnuplot draws (at {first_up})")
    script = (keep / "plot.gp").read_text()
    expect('keyentry t "before.csv"' in script and 'keyentry t "after.csv"' in script,
           "the legend names each file")
    expect('lc rgb "#809400d3" t "roll"' in script and 'lc rgb "#9400d3" t "roll"' in script,
           "roll in the same colour in both, the first log's faint")

    run = plot(before, "--over", after, "--align", "mode:full", "--keep-data", keep, "--out", folder / "mode.png")
    found = offsets(run)
    expect(run.returncode == 0 and len(found) == 2 and abs(found[0] - 0.5) < 1e-9 and abs(found[1] - 3.0) < 1e-9,
           f"full control found where it began: 0.5 s and 3.0 s ({run.stdout.strip()} {run.stderr.strip()})")
    expect(abs(data(keep / "log2" / "angle.dat", 1)[0][0] + 3.0) < 1e-9, "the second log starts 3.0 s before its time 0")

    # The session's telemetry.csv: other names, the console's clock, empty fields before a group is heard.
    console = header("pc/core/telemetry_csv.cpp", r"telemetry_csv_header\(\)")
    rows = [{"pc_time_ms": 5000 + 20 * i, "mode": 5, "sp_roll": 800 if i >= shift else 0,
             **{k: (None if i < 10 else 0) for k in ("phi", "theta", "psi", "p", "q", "r")}}
            for shift in (40, 90) for i in range(200)]
    write_log(folder / "t1.csv", console, rows[:200])
    write_log(folder / "t2.csv", console, rows[200:])
    run = plot(folder / "t1.csv", "--over", folder / "t2.csv", "--align", "step:sp_roll", "--out", folder / "t.png")
    found = offsets(run)
    expect(run.returncode == 0 and len(found) == 2 and abs(found[0] - 0.8) < 1e-9 and abs(found[1] - 1.8) < 1e-9,
           f"telemetry.csv: each step found at 0.8 s and 1.8 s ({run.stdout.strip()} {run.stderr.strip()})")


def errors(folder):
    log = header("pc/core/log_csv.cpp", r"log_header\(const wire::TelemetryLogRecord&\)")
    sensor = header("pc/core/log_csv.cpp", r"log_header\(const wire::SensorLogRecord&\)")
    good, grounded, gyro = folder / "good.csv", folder / "grounded.csv", folder / "sensor.csv"
    write_log(good, log, flight(0, full_at=50, step_at=100, lines=200))
    write_log(grounded, log, flight(0, full_at=10_000, step_at=10_000, lines=200))  # never flies, no step
    write_log(gyro, sensor, [{"line": i, "time_us": 1000 * i} for i in range(64)])
    out = folder / "out.png"

    def refused(args, status, words, what):
        run = plot(*args, "--out", out)
        expect(run.returncode == status and all(w in run.stderr for w in words) and "Traceback" not in run.stderr,
               f"{what}: status {status}, says {words} ({run.returncode}: {run.stderr.strip()})")

    refused([good, "--over", folder / "missing.csv"], 1, ["missing.csv", "No such file"], "a missing second log")
    refused([good, "--over", gyro], 1, ["same kind", "good.csv: QR telemetry log", "sensor.csv: QR sensor log"],
            "a sensor log over a telemetry log")
    refused([good, "--over", grounded, "--align", "mode:full"], 1, ["grounded.csv", "mode:full", "no row in mode full"],
            "a log that never enters the mode")
    refused([good, "--over", grounded, "--align", "step:roll_sp_1e-4rad"], 1,
            ["grounded.csv", "step:roll_sp_1e-4rad", "never moves"], "a log without the step")
    refused([good, "--over", good, "--align", "step:sp_roll"], 1, ["good.csv", "no sp_roll column"],
            "a column the log does not have")
    refused([gyro, "--over", gyro, "--align", "mode:full"], 1, ["sensor.csv", "no mode column"], "a mode in a sensor log")
    refused([good, "--over", good, "--align", "mode:hover"], 2, ["'hover' is not a mode", "full"],
            "a mode that does not exist")
    refused([good, "--over", good, "--align", "roll"], 2, ["not an event", "step:COLUMN"], "an event that does not exist")


def panel(script, ylabel):
    """The gnuplot lines of the panel with this label: from its ylabel to the next panel's."""
    start = script.find(f'set ylabel "{ylabel}"')
    end = script.find("set ylabel", start + 1)
    return "" if start < 0 else script[start:end if end > 0 else len(script)]


def telemetry(folder):
    console = header("pc/core/telemetry_csv.cpp", r"telemetry_csv_header\(\)")
    # 1 s at 50 rows a second: the height group heard from row 5, valid from row 10, climbing 10 mm a
    # row from 1.1 m; the lift set-point rising 300 -> 349 under engines at 400.
    rows = [{"pc_time_ms": 20 * i, "mode": 5, "sp_lift": 300 + i, "hover_lift": 0,
             **{f"engine_{e}": 400 for e in ("front", "right", "back", "left")},
             "height_mm": None if i < 5 else 1000 + 10 * i, "climb_mm_s": None if i < 5 else 500,
             "height_flags": None if i < 5 else int(i >= 10)} for i in range(50)]
    write_log(folder / "telemetry.csv", console, rows)
    keep = folder / "keep"
    keep.mkdir()
    run = plot(folder / "telemetry.csv", "--keep-data", keep, "--out", folder / "t.png")
    expect(run.returncode == 0, f"telemetry.csv with height drawn ({run.stderr.strip()})")
    script = (keep / "plot.gp").read_text()
    height = panel(script, "height (m)")
    expect('height.dat" u 1:2 w l' in height and 't "height"' in height, "a height panel with the height on it")
    points = data(keep / "log1" / "height.dat", 1)
    expect(len(points) == 40 and abs(points[0][0] - 0.2) < 1e-9 and abs(points[0][1] - 1.1) < 1e-9,
           f"height from the first valid row (0.2 s, 1.1 m), in metres: {points[:1]}, {len(points)} points")
    engines = panel(script, "engine (0..1000)")
    expect('lift.dat" u 1:2 w l dt 2 lw 2 lc rgb "#000000" t "lift set-point"' in engines,
           "the lift set-point on the engines' panel, dashed, black")
    expect(data(keep / "log1" / "lift.dat", 1)[-1][1] == 349, "the lift set-point's values as logged")

    # The QR's telemetry log records no height: no panel, and the title says why.
    log = header("pc/core/log_csv.cpp", r"log_header\(const wire::TelemetryLogRecord&\)")
    write_log(folder / "qr.csv", log, flight(0, full_at=50, step_at=100, lines=200))
    run = plot(folder / "qr.csv", "--keep-data", keep, "--out", folder / "q.png")
    script = (keep / "plot.gp").read_text()
    expect(run.returncode == 0 and not panel(script, "height (m)") and "no height: this log does not record it" in script,
           f"a QR telemetry log: no height panel, the title says so ({run.stderr.strip()})")
    expect('t "lift set-point"' in panel(script, "engine (0..1000)"), "its lift set-point on the engines' panel")
    # A telemetry.csv from before the height columns still draws.
    write_log(folder / "old.csv", console[:-4], rows)
    run = plot(folder / "old.csv", "--out", folder / "o.png")
    expect(run.returncode == 0, f"a telemetry.csv without height columns ({run.stderr.strip()})")


def main():
    with tempfile.TemporaryDirectory() as folder:
        {"align": align, "errors": errors, "telemetry": telemetry}[sys.argv[1]](pathlib.Path(folder))


if __name__ == "__main__":
    main()
