#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the sample measurements of this folder from runs of the lab itself (rigidlab-cli run
--trace), with other parameters than the scenes' own and Gaussian noise, in each layout the lab
reads. Run from the source tree: make_samples.py BUILD/app/rigidlab-cli.

  ball_*: ball_floor.json with the ball's restitution 0.72 (the scene says 0.8), filmed at
          60 frames a second for 1.6 s, y with sigma = 2 mm; ball_bounces_phyphox.csv: the
          bounce times (from a run at 0.1 ms steps) with sigma = 1 ms.
  box_*:  box_slide.json with the pair's friction 0.33 (the scene says 0.4), 60 frames a
          second for 1 s, x with sigma = 3 mm.
"""
import json, os, random, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def trace(cli, scene, edit, seconds, dt=None):
    with open(os.path.join(HERE, scene)) as f:
        doc = json.load(f)
    edit(doc)
    with tempfile.TemporaryDirectory() as tmp:
        path, out = os.path.join(tmp, "s.json"), os.path.join(tmp, "t.csv")
        with open(path, "w") as f:
            json.dump(doc, f)
        step = ["--dt", str(dt)] if dt else []
        subprocess.run([cli, "run", path, "--time", str(seconds), "--trace", out] + step,
                       check=True, stdout=subprocess.DEVNULL)
        rows = [l.split(",") for l in open(out).read().split("\n")[1:] if l]
    return [(float(r[1]), float(r[3]), float(r[4]), float(r[7])) for r in rows]  # t x y vy


def at(rows, t, k):
    for a, b in zip(rows, rows[1:]):
        if a[0] <= t <= b[0]:
            w = (t - a[0]) / (b[0] - a[0]) if b[0] > a[0] else 0
            return a[k] + w * (b[k] - a[k])
    return rows[-1][k]


def main(cli):
    rng = random.Random(33)
    def ball(doc):
        doc["bodies"][1]["restitution"] = 0.72
    def box(doc):
        for b in doc["bodies"]:
            b["friction"] = 0.33
    ball_rows = trace(cli, "ball_floor.json", ball, 3.0)
    box_rows = trace(cli, "box_slide.json", box, 1.0)
    frames = [i / 60 for i in range(97)]
    ys = [at(ball_rows, t, 2) + rng.gauss(0, 0.002) for t in frames]
    xs = [at(box_rows, t, 1) + rng.gauss(0, 0.003) for t in frames[:61]]
    bys = [at(box_rows, t, 2) for t in frames[:61]]
    write("ball_tracker.csv", "mass A\nt,x,y\n",
          ["%.4f,%.4f,%.4f" % (t, 0.0, y) for t, y in zip(frames, ys)])
    write("ball_phyphox.csv", '"Time (s)","Height (m)"\n',
          ["%.6E,%.6E" % (t, y) for t, y in zip(frames, ys)])
    write("ball_plain.csv", "", ["%.4f,%.4f" % (t, y) for t, y in zip(frames, ys)])
    comma = lambda s: s.replace(".", ",")
    write("box_tracker_cs.txt", "kvádr\nt\tx\ty\n",
          [comma("%.4f\t%.4f\t%.4f" % (t, x, y)) for t, x, y in zip(frames, xs, bys)])
    write("box_phyphox_cs.csv", '"Time (s)";"Position x (cm)"\n',
          [comma("%.4f;%.2f" % (t, 100 * x)) for t, x in zip(frames, xs)])
    write("box_plain.csv", "", ["%.4f,%.4f,%.4f" % (t, x, y) for t, x, y in zip(frames, xs, bys)])
    # Bounces: the vertical velocity turns from down to up, in a run of 0.1 ms steps (the
    # scene's 2 ms would put each bounce up to a step late).
    fine = trace(cli, "ball_floor.json", ball, 3.0, 0.0001)
    bounces = [b[0] for a, b in zip(fine, fine[1:]) if a[3] < 0 <= b[3]][:8]
    write("ball_bounces_phyphox.csv", '"Time (s)"\n',
          [comma("%.4f" % (t + rng.gauss(0, 0.001))) for t in bounces])


def write(name, header, rows):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(header + "\n".join(rows) + "\n")


if __name__ == "__main__":
    main(sys.argv[1])
