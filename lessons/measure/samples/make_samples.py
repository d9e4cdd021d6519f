#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the sample measurements of this folder from exact models (closed-form motion, no time
step, nothing of the lab's own engine), with other parameters than the scenes' own and seeded
Gaussian noise, in each layout the lab reads. Run it from anywhere: make_samples.py. The same
files come out every time (the noise is seeded), so a change shows in git diff.

  ball_*: ball_floor.json's ball (radius 5 cm, its centre dropped from 1.05 m onto the floor's
          top at 0 m, g = 9.81 m/s^2) with the coefficient of restitution 0.72 (the scene says
          0.8): each flight a parabola, each bounce leaving with e times the speed it arrived
          with. Filmed at 60 frames a second for 1.6 s, y with sigma = 2 mm;
          ball_bounces_phyphox.csv: the first eight bounce times with sigma = 1 ms.
  box_*:  box_slide.json's box pushed off at 3 m/s with the pair's friction 0.33 (the scene
          says 0.4): x = x0 + v0 t - mu g t^2 / 2 until it stops, then still. 60 frames a
          second for 1 s, x with sigma = 3 mm.
"""
import math, os, random

HERE = os.path.dirname(os.path.abspath(__file__))

G = 9.81          # [m/s^2], both scenes' gravity
FPS = 60          # frames a second
E_BALL = 0.72     # the ball's coefficient of restitution (the floor's is 0: the larger counts)
MU_BOX = 0.33     # the box's and the floor's friction (the contact: their geometric mean)
SEED = 33


def ball_flights(e, y0=1.05, contact=0.05, bounces=40):
    """The ball's flights: (start time, centre height, upward speed) at each flight's start,
    the first from rest at y0; contact is the centre's height on the floor."""
    flights = [(0.0, y0, 0.0)]
    t, y, v = flights[0]
    for _ in range(bounces):
        down = math.sqrt(v * v + 2 * G * (y - contact))  # speed at the floor
        t += (v + down) / G
        y, v = contact, e * down
        flights.append((t, y, v))
    return flights


def ball_height(flights, t):
    start = max(f for f in flights if f[0] <= t)
    s = t - start[0]
    return start[1] + start[2] * s - 0.5 * G * s * s


def box_x(t, x0=-1.0, v0=3.0, mu=MU_BOX):
    stop = v0 / (mu * G)
    s = min(t, stop)
    return x0 + v0 * s - 0.5 * mu * G * s * s


def main():
    rng = random.Random(SEED)
    frames = [i / FPS for i in range(97)]
    flights = ball_flights(E_BALL)
    ys = [ball_height(flights, t) + rng.gauss(0, 0.002) for t in frames]
    xs = [box_x(t) + rng.gauss(0, 0.003) for t in frames[:61]]
    bys = [0.05 for _ in frames[:61]]  # the box's centre on the floor
    bounces = [f[0] for f in flights[1:9]]
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
    write("ball_bounces_phyphox.csv", '"Time (s)"\n',
          [comma("%.4f" % (t + rng.gauss(0, 0.001))) for t in bounces])


def write(name, header, rows):
    with open(os.path.join(HERE, name), "w", encoding="utf-8", newline="\n") as f:
        f.write(header + "\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
