#!/usr/bin/env python3
"""scripts/docfigures against a made-up benchmark output: a document that quotes the run passes,
one figure or one block line off fails with the place named, a key the run does not print fails,
and writing puts the run's figures back in the document's own notation."""
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = ROOT / "scripts/docfigures"
RUN = ('{"mode":"full","tick_instr_mean":3140,"tasks":{"mixer":{"mean":290}}}\n'
       '{"summary":"made up","float_over_fixed":9.39}\n')
GOOD = ("The tick takes 3 140<!-- figure devboard-bench full.tick_instr_mean --> instructions, "
        "the mixer 290<!-- figure devboard-bench full.tasks.mixer.mean -->, float is "
        "9.4<!-- figure devboard-bench summary.float_over_fixed -->x slower.\n\n"
        "<!-- figures devboard-bench -->\n```\n" + RUN + "```\n")


def docfigures(doc, *extra):
    run = doc.with_name("run.json")
    run.write_text(RUN)
    return subprocess.run([sys.executable, str(TOOL), "--output", f"devboard-bench={run}",
                           *extra, str(doc)], capture_output=True, text=True)


def expect(condition, message):
    if not condition:
        sys.exit(f"FAIL: {message}")
    print(f"ok: {message}")


def main():
    with tempfile.TemporaryDirectory() as folder:
        doc = pathlib.Path(folder) / "page.md"
        doc.write_text(GOOD)
        run = docfigures(doc, "--check")
        expect(run.returncode == 0, f"a page quoting the run passes ({run.stderr.strip()})")

        doc.write_text(GOOD.replace("3 140<!--", "3 141<!--"))
        run = docfigures(doc, "--check")
        expect(run.returncode == 1 and "page.md:1: says 3 141" in run.stderr and "prints 3 140" in run.stderr,
               f"one figure off fails and names the place ({run.stderr.strip()})")

        doc.write_text(GOOD.replace("9.4<!--", "9.3<!--"))
        expect(docfigures(doc, "--check").returncode == 1, "a figure off in its last written decimal fails")

        doc.write_text(GOOD.replace('"mean":290}}}\n{', '"mean":291}}}\n{'))
        run = docfigures(doc, "--check")
        expect(run.returncode == 1 and "block is not the run's output" in run.stderr,
               "a block line off fails")

        doc.write_text(GOOD.replace("tasks.mixer.mean", "tasks.filter.mean"))
        run = docfigures(doc, "--check")
        expect(run.returncode == 1 and "prints no number at full.tasks.filter.mean" in run.stderr,
               "a key the run does not print fails")

        doc.write_text(GOOD.replace("3 140<!--", "2 979<!--").replace("9.4<!--", "8.5<!--")
                       .replace('"mean":290}}}\n{', '"mean":1}}}\n{'))
        run = docfigures(doc)
        expect(run.returncode == 0 and doc.read_text() == GOOD,
               "writing puts the run's figures back, in the page's notation")

        run = subprocess.run([sys.executable, str(TOOL), "--elf", "nonsense=x"], capture_output=True, text=True)
        expect(run.returncode == 2 and "NAME one of" in run.stderr, "a bad argument exits 2 and says why")


if __name__ == "__main__":
    main()
