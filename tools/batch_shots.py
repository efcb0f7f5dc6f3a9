#!/usr/bin/env python3
"""Writes N random single shots as JSON lines for `baize batch` (docs/positional.md).

    python3 tools/batch_shots.py 2000 > out/shots.jsonl          # seed 1
    python3 tools/batch_shots.py 2000 --seed 7 > out/other.jsonl

Each line is a whole scene with an "id": the cue ball and one object ball anywhere on the 9 ft
table (apart, and clear of the pockets), struck at 0.5-4 m/s towards the object ball give or take 10 deg, with any tip offset
inside the miscue limit. Python's random module is seeded, so the file depends only on N and the
seed (for a given Python version's Mersenne Twister, which is specified). `baize batch` answers
each line with a result in the format of docs/results.md (`first_ball_hit`, `pocketed`,
`final_positions_m`, ..., and the line's scene embedded); the "id" here joins results to shots.
"""
import argparse
import json
import math
import random

R = 0.028575  # pool ball radius, m
HALF_LENGTH, HALF_WIDTH = 2.54 / 2 - R, 1.27 / 2 - R  # where a centre may be on the 9 ft table
# The pockets' points (corners of the noses' rectangle, middles of the long sides), m, and how near
# a centre may come to one: farther than any capture circle reaches onto the table, so that no
# ball starts in a pocket (the table file's capture circles reach about 0.055 m from these).
POCKETS = [(sx * 2.54 / 2, sy * 1.27 / 2) for sx in (-1, 0, 1) for sy in (-1, 1)]
POCKET_CLEARANCE = 0.12


def on_the_cloth(p):
    return all(math.dist(p, pocket) > POCKET_CLEARANCE for pocket in POCKETS)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("count", type=int)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    for i in range(args.count):
        while True:
            cue = [rng.uniform(-HALF_LENGTH, HALF_LENGTH), rng.uniform(-HALF_WIDTH, HALF_WIDTH)]
            one = [rng.uniform(-HALF_LENGTH, HALF_LENGTH), rng.uniform(-HALF_WIDTH, HALF_WIDTH)]
            if math.dist(cue, one) > 2 * R + 0.001 and on_the_cloth(cue) and on_the_cloth(one):
                break
        heading = math.degrees(math.atan2(one[1] - cue[1], one[0] - cue[0]))
        radius, angle = 0.45 * math.sqrt(rng.random()), rng.uniform(0, 2 * math.pi)
        line = {"id": f"shot-{i}", "table": "pool-9ft", "ball_set": "pool",
                "balls": {"cue": [round(c, 5) for c in cue], "1": [round(c, 5) for c in one]},
                "shot": {"heading_deg": round(heading + rng.uniform(-10, 10), 4),
                         "speed_mps": round(rng.uniform(0.5, 4), 4),
                         "side": round(radius * math.cos(angle), 4),
                         "height": round(radius * math.sin(angle), 4)}}
        print(json.dumps(line))


if __name__ == "__main__":
    main()
