#!/usr/bin/env python3
"""Writes assets/suites/positional-drills.json from closed forms, without running the simulator,
and the shipped stun, follow and draw scenes it uses (assets/scenes/{stun,follow,draw}-shot.json):

    python3 tools/positional_suite.py assets

Every expected cue-ball region comes from the closed forms of docs/physics-notes (section 2:
sliding and rolling on the cloth; section 3: the head-on frictional impact; section 4: the cue
strike), worked out here step by step; docs/positional.md states the derivation. Nothing here is
fitted to the simulator's output.
"""
import json
import math
import os
import sys

G = 9.81  # m/s^2, as physics::ClothParams
CUE_MASS = 0.54  # kg, physics::CueStrikeParams default
TIP_E = 0.75  # tip restitution, same

POOL = dict(table="pool-9ft", ball_set="pool", R=0.028575, m=0.17, mu_s=0.2, mu_r=0.01, e=0.95,
            L=2.54, W=1.27, corner_mouth=0.116)
SNOOKER = dict(table="snooker-12ft", ball_set="snooker", R=0.02625, m=0.1406, mu_s=0.212,
               mu_r=0.0128, e=0.89, L=3.569, W=1.778, corner_mouth=0.086)
# Alciatore's fit of ball-ball friction against the contact slip speed u (m/s): physics-notes 3.
FIT_A, FIT_B, FIT_C = 9.951e-3, 0.108, 1.088

# A stop shot, as players define it: the cue ball stays within a few centimetres of where it met
# the object ball. The closed form puts it a few millimetres forward of that point.
STOP_RADIUS_M = 0.03
# A position zone for follow and draw: the area a player aims the cue ball at, 5 cm across each way.
POSITION_RADIUS_M = 0.05


def ball_speed(cue_speed, b, p):
    """Level strike at height b (units of R): ball speed v0 and spin R*omega (physics-notes 4)."""
    v0 = (1 + TIP_E) * cue_speed / (1 + p["m"] / CUE_MASS + 2.5 * b * b)
    return v0, 2.5 * b * v0


def cue_speed_for(v0, b, p):
    return v0 * (1 + p["m"] / CUE_MASS + 2.5 * b * b) / (1 + TIP_E)


def travel(v0, rw0, distance, p):
    """Speed and R*omega (1D, + forward) after `distance` m on the cloth (physics-notes 2)."""
    a_s, a_r = p["mu_s"] * G, p["mu_r"] * G
    slip = v0 - rw0
    t_roll = 2 * abs(slip) / (7 * a_s)
    sign = 1 if slip > 0 else -1
    d_slide = v0 * t_roll - 0.5 * sign * a_s * t_roll**2
    if distance <= d_slide:
        # v0 t - sign a_s t^2 / 2 = distance, the earlier root.
        t = (v0 - math.sqrt(v0 * v0 - 2 * sign * a_s * distance)) / (sign * a_s)
        return v0 - sign * a_s * t, rw0 + 2.5 * sign * a_s * t
    v_roll = v0 - sign * a_s * t_roll
    v = math.sqrt(v_roll**2 - 2 * a_r * (distance - d_slide))
    return v, v


def after_head_on(v, rw, p, friction=True):
    """Cue ball right after a full hit on a resting ball: Newton's restitution along the line; the
    vertical slip R*omega at the contact meets friction mu(u) * normal impulse, which turns the
    cue ball's spin back towards zero by (5/2) mu (1 + e)/2 v (physics-notes 3)."""
    v1 = (1 - p["e"]) / 2 * v
    if not friction or rw == 0:
        return v1, rw
    mu = FIT_A + FIT_B * math.exp(-FIT_C * abs(rw))
    change = 2.5 * mu * (1 + p["e"]) / 2 * v
    return v1, rw - math.copysign(min(change, abs(rw)), rw)


def run_out(v1, rw1, p):
    """Displacement (m, + forward) of a ball from (v1, R*omega1) to rest."""
    a_s, a_r = p["mu_s"] * G, p["mu_r"] * G
    v_roll = 5 / 7 * v1 + 2 / 7 * rw1  # physics-notes 2: whatever mu_s is
    slide = (v1 * v1 - v_roll * v_roll) / (2 * a_s) * (1 if v1 > v_roll else -1)
    roll = math.copysign(v_roll * v_roll / (2 * a_r), v_roll)
    return slide + roll


def diagonal_line(p, object_from_corner, travel_before_contact):
    """Balls on the diagonal into the +x,+y corner pocket (its axis is 45 deg)."""
    u = (1 / math.sqrt(2), 1 / math.sqrt(2))
    corner = (p["L"] / 2, p["W"] / 2)
    obj = (corner[0] - object_from_corner * u[0], corner[1] - object_from_corner * u[1])
    ghost = (obj[0] - 2 * p["R"] * u[0], obj[1] - 2 * p["R"] * u[1])
    cue = (ghost[0] - travel_before_contact * u[0], ghost[1] - travel_before_contact * u[1])
    return u, obj, ghost, cue


def at(point, u, s):
    return [round(point[0] + s * u[0], 4), round(point[1] + s * u[1], 4)]


def r4(x):
    return round(x, 4)



# --- A ball's path on the cloth with rails, for the two-rail case -------------------------------
# Closed forms of physics-notes section 2 (sliding: constant deceleration mu_s g along the fixed slip
# direction, the spin turning at 5 mu_s g / 2R; rolling: mu_r g along the velocity) between rails;
# at a rail the simple rule of docs/scenes.md (the normal velocity reverses times 0.74, the head-on
# rebound of a rolling ball on the pool tables' calibrated rails, docs/calibrate.md; the velocity
# along the rail and the spin are kept). This is the naive player's model of a rail; the simulator
# uses the Mathavan 2010 cushion model, which also turns the ball by the friction at the nose
# (docs/positional.md compares the two).
RAIL_RESTITUTION = 0.74


def first_root(a, b, c):
    """Smallest t > 1e-12 with a t^2 + b t + c = 0, or None."""
    roots = []
    if abs(a) < 1e-15:
        if abs(b) > 1e-15:
            roots = [-c / b]
    else:
        disc = b * b - 4 * a * c
        if disc >= 0:
            q = math.sqrt(disc)
            roots = [(-b - q) / (2 * a), (-b + q) / (2 * a)]
    roots = [t for t in roots if t > 1e-12]
    return min(roots) if roots else None


def trace(pos, vel, spin, p, rails_wanted=None):
    """pos, vel: [x, y]; spin: [w_x, w_y] (rad/s). Returns the stop point and the rails touched."""
    R, a_s, a_r = p["R"], p["mu_s"] * G, p["mu_r"] * G
    lim = (p["L"] / 2 - R, p["W"] / 2 - R)
    rails = []
    pos, vel, spin = list(pos), list(vel), list(spin)
    for _ in range(100):
        slip = (vel[0] - R * spin[1], vel[1] + R * spin[0])
        slip_n = math.hypot(*slip)
        speed = math.hypot(*vel)
        if speed < 1e-9 and slip_n < 1e-9:
            return pos, rails
        if slip_n > 1e-9:
            acc = (-a_s * slip[0] / slip_n, -a_s * slip[1] / slip_n)
            t_end = 2 * slip_n / (7 * a_s)
        else:
            acc = (-a_r * vel[0] / speed, -a_r * vel[1] / speed)
            t_end = speed / a_r
        hit, axis = t_end, None
        for k in range(2):
            for wall in (lim[k], -lim[k]):
                t = first_root(0.5 * acc[k], vel[k], pos[k] - wall)
                if t is not None and t < hit and (vel[k] + acc[k] * t) * wall > 0:
                    hit, axis = t, k
        t = hit
        pos = [pos[k] + vel[k] * t + 0.5 * acc[k] * t * t for k in range(2)]
        if slip_n > 1e-9:
            spin = [spin[0] - 2.5 * a_s / R * t * acc[1] / a_s,
                    spin[1] + 2.5 * a_s / R * t * acc[0] / a_s]
        vel = [vel[k] + acc[k] * t for k in range(2)]
        if axis is None:
            if slip_n > 1e-9:  # now rolling
                spin = [-vel[1] / R, vel[0] / R]
            else:
                return pos, rails
        else:
            vel[axis] = -RAIL_RESTITUTION * vel[axis]
            rails.append(("x" if axis == 0 else "y") + ("+" if pos[axis] > 0 else "-"))
    raise RuntimeError("no rest after 100 phases")


cases = []
notes = {}

# 1. Stop shot: backspin b chosen so the spin has just worn off at contact: over D the sliding
#    ball's R*omega rises from (5/2) b v0 to 0 at t = -b v0 / (mu_s g), so D = (v0^2 / mu_s g)(-b -
#    b^2/2). The cue ball keeps (1 - e)/2 of its speed and no spin.
# Scenes the suite shares with assets/scenes (the shipped stun, follow and draw shots): written there
# and referenced by path, so that each is defined once.
shipped_scenes = {}


def shipped_scene(name, scene):
    shipped_scenes[name] = scene
    return "../scenes/" + name + ".json"


p = POOL
D, b = 0.6, -0.3
v0 = math.sqrt(D * p["mu_s"] * G / (-b - b * b / 2))
V = cue_speed_for(v0, b, p)
u, obj, ghost, cue = diagonal_line(p, 0.707, D)
v, rw = travel(v0, 2.5 * b * v0, D, p)
forward = run_out(*after_head_on(v, rw, p), p)
notes["stop-shot"] = dict(cue_speed=V, arrival_speed=v, arrival_rw=rw, predicted_forward_m=forward)
cases.append({
    "name": "stop-shot",
    "description": f"Full hit into the top-right corner with stun: the spin wears off at contact "
                   f"(b = {b}, D = {D} m, arrival {v:.3f} m/s); the cue ball rolls on only "
                   f"{forward * 1000:.1f} mm (closed form); expected within {STOP_RADIUS_M} m of "
                   f"the contact point",
    "scene": shipped_scene("stun-shot", {"table": p["table"], "ball_set": p["ball_set"],
              "balls": {"cue": at(cue, u, 0), "1": at(obj, u, 0)},
              "shot": {"aim_at": "1", "speed_mps": r4(V), "height": b}}),
    "expect": {"pocketed": ["1"], "first_hit": "1", "no_foul": True,
               "cue_ball_stops_in": {"circle": at(ghost, u, 0) + [STOP_RADIUS_M]}},
})

# 2. Follow into position: natural roll from the strike (b = 0.4 R leaves the ball rolling), rolling
#    over D, full hit; the cue ball keeps (1-e)/2 v and its topspin less the ball-ball friction's
#    share, then rolls at 5/7 v1 + 2/7 R omega1.
D, b, v_arrive = 0.5, 0.4, 1.0
v0 = math.sqrt(v_arrive**2 + 2 * p["mu_r"] * G * D)
V = cue_speed_for(v0, b, p)
u, obj, ghost, cue = diagonal_line(p, 1.0, D)
v, rw = travel(v0, v0, D, p)
follow = run_out(*after_head_on(v, rw, p), p)
naive = run_out(*after_head_on(v, rw, p, friction=False), p)
notes["follow"] = dict(cue_speed=V, arrival_speed=v, predicted_follow_m=follow,
                       without_ball_friction_m=naive)
cases.append({
    "name": "follow-into-position",
    "description": f"Rolling full hit at {v:.3f} m/s into the top-right corner; the cue ball follows "
                   f"{follow:.3f} m (closed form with the ball-ball friction; {naive:.3f} m without "
                   f"it) and must stop within {POSITION_RADIUS_M} m of that spot",
    "scene": shipped_scene("follow-shot", {"table": p["table"], "ball_set": p["ball_set"],
              "balls": {"cue": at(cue, u, 0), "1": at(obj, u, 0)},
              "shot": {"aim_at": "1", "speed_mps": r4(V), "height": b}}),
    "expect": {"pocketed": ["1"], "cue_ball_not_pocketed": True, "no_foul": True,
               "cue_ball_stops_in": {"circle": at(ghost, u, follow) + [POSITION_RADIUS_M]}},
})

# 3. Draw back: full draw (b = -0.4: R omega0 = -v0), the ball slides all the way (D is shorter
#    than the sliding distance); after the hit the backspin, less the friction's share, pulls it
#    back: it slides to 5/7 v1 + 2/7 R omega1 < 0 and rolls back.
D, b, V = 0.4, -0.4, 2.0
v0, rw0 = ball_speed(V, b, p)
u, obj, ghost, cue = diagonal_line(p, 0.8, D)
v, rw = travel(v0, rw0, D, p)
draw = run_out(*after_head_on(v, rw, p), p)
naive = run_out(*after_head_on(v, rw, p, friction=False), p)
notes["draw"] = dict(cue_speed=V, arrival_speed=v, arrival_rw=rw, predicted_draw_m=draw,
                     without_ball_friction_m=naive)
cases.append({
    "name": "draw-back",
    "description": f"Full draw (b = {b}) at {V} m/s over {D} m, arriving at {v:.3f} m/s with R "
                   f"omega = {rw:.3f} m/s; the cue ball comes back {-draw:.3f} m (closed form with "
                   f"the ball-ball friction; {-naive:.3f} m without it) and must stop within "
                   f"{POSITION_RADIUS_M} m of that spot",
    "scene": shipped_scene("draw-shot", {"table": p["table"], "ball_set": p["ball_set"],
              "balls": {"cue": at(cue, u, 0), "1": at(obj, u, 0)},
              "shot": {"aim_at": "1", "speed_mps": r4(V), "height": b}}),
    "expect": {"pocketed": ["1"], "cue_ball_not_pocketed": True, "no_foul": True,
               "cue_ball_stops_in": {"circle": at(ghost, u, draw) + [POSITION_RADIUS_M]}},
})

# 4. Snooker: the black off its spot into the top-right corner pocket with a stop shot, from a cue
#    ball on the line from the pocket's mouth centre through the black. Two cases: where the cue
#    ball stops, and whether it leaves a straight shot at a red into the bottom-middle pocket.
p = SNOOKER
half_l, half_w = p["L"] / 2, p["W"] / 2
black = (half_l - 0.324, 0.0)
setback = p["corner_mouth"] / math.sqrt(2) / 2  # mouth centre from the corner along each rail
mouth = (half_l - setback, half_w - setback)
dx, dy = mouth[0] - black[0], mouth[1] - black[1]
n = math.hypot(dx, dy)
u = (dx / n, dy / n)
D, b = 0.5, -0.3
v0 = math.sqrt(D * p["mu_s"] * G / (-b - b * b / 2))
V = cue_speed_for(v0, b, p)
ghost = (black[0] - 2 * p["R"] * u[0], black[1] - 2 * p["R"] * u[1])
cue = (ghost[0] - D * u[0], ghost[1] - D * u[1])
v, rw = travel(v0, 2.5 * b * v0, D, p)
forward = run_out(*after_head_on(v, rw, p), p)
stop_at = at(ghost, u, forward)
red = [0.35, -0.55]
notes["black"] = dict(cue_speed=V, arrival_speed=v, predicted_forward_m=forward, stop_at=stop_at)
scene = {"table": p["table"], "ball_set": p["ball_set"],
         "balls": {"cue": at(cue, u, 0), "black": at(black, u, 0), "red1": red},
         "shot": {"aim_at": "black", "speed_mps": r4(V), "height": b}}
cases.append({
    "name": "black-off-spot-stop",
    "description": f"Snooker black off its spot into the top-right corner with stun (b = {b}, "
                   f"D = {D} m): the cue ball rolls on {forward * 1000:.1f} mm (e = 0.89 leaves "
                   f"it 5.5 % of its speed); expected within {STOP_RADIUS_M} m of the contact point",
    "scene": scene,
    "expect": {"pocketed": ["black"], "not_pocketed": ["red1"], "first_hit": "black",
               "no_foul": True,
               "cue_ball_stops_in": {"circle": at(ghost, u, 0) + [STOP_RADIUS_M]}},
})
cases.append({
    "name": "black-off-spot-leave",
    "description": "The same shot: from where the closed form stops the cue ball, the red at "
                   f"{red} is a cut into the bottom-middle pocket with nothing in the way",
    "scene": scene,
    "expect": {"pocketed": ["black"],
               "cue_ball_stops_in": {"straight_shot_at": "red1", "into_pocket": "bottom-middle"}},
})

# 5. Two-rail position: a stun cut of 35 deg into the top-right corner; the cue ball leaves along
#    the tangent line (90 deg rule: no spin at contact; the normal part keeps (1-e)/2 of the
#    approach, and the throw friction mu(u) J takes from the tangential part), goes off the right
#    and bottom rails and must stop where it has a straight shot at the 2 into the bottom-left
#    corner. The stop point comes from trace() above; ball 2 is placed 0.6 m further along the
#    line from the bottom-left pocket's mouth through that point, so the region is a fan of cut
#    angles around it rather than a fitted circle.
p = POOL
cut, D, b, v_arrive = math.radians(35), 0.9, -0.25, 0
u = (1 / math.sqrt(2), 1 / math.sqrt(2))
perp = (u[1], -u[0])  # the tangent line's direction, towards the bottom-right
corner = (p["L"] / 2, p["W"] / 2)
obj = (corner[0] - 0.6 * u[0], corner[1] - 0.6 * u[1])
ghost = (obj[0] - 2 * p["R"] * u[0], obj[1] - 2 * p["R"] * u[1])
# The cue ball comes from the upper-left side of the line, so it departs along +perp.
d = (math.cos(cut) * u[0] + math.sin(cut) * perp[0], math.cos(cut) * u[1] + math.sin(cut) * perp[1])
cue = (ghost[0] - D * d[0], ghost[1] - D * d[1])
# Stun at contact: D = (v0^2 / mu_s g)(-b - b^2/2) fixes v0 for this b.
v0 = math.sqrt(D * p["mu_s"] * G / (-b - b * b / 2))
V = cue_speed_for(v0, b, p)
v, rw = travel(v0, 2.5 * b * v0, D, p)
normal_speed, tangent_speed = v * math.cos(cut), v * math.sin(cut)
J_per_m = (1 + p["e"]) / 2 * normal_speed
mu = FIT_A + FIT_B * math.exp(-FIT_C * tangent_speed)
# Friction stops at the value that ends the sliding of the contact (both balls turn: 2 (1 + 5/2)).
throw = min(mu * J_per_m, tangent_speed / 7)
after = [(1 - p["e"]) / 2 * normal_speed * u[k] + (tangent_speed - throw) * perp[k]
         for k in range(2)]
stop, rails = trace(ghost, after, [0.0, 0.0], p)
notes["two-rail"] = dict(cue_speed=V, arrival_speed=v, rails=rails, stop=stop)
mouth0 = (-p["L"] / 2 + p["corner_mouth"] / math.sqrt(2) / 2,
          -p["W"] / 2 + p["corner_mouth"] / math.sqrt(2) / 2)
to_mouth = (mouth0[0] - stop[0], mouth0[1] - stop[1])
n = math.hypot(*to_mouth)
two = [r4(stop[0] + 0.5 * to_mouth[0] / n), r4(stop[1] + 0.5 * to_mouth[1] / n)]
scene = {"table": p["table"], "ball_set": p["ball_set"],
         "balls": {"cue": at(cue, u, 0), "1": at(obj, u, 0), "2": two},
         "shot": {"heading_deg": round(math.degrees(math.atan2(d[1], d[0])), 6),
                  "speed_mps": r4(V), "height": b}}
cases.append({
    "name": "two-rail-position",
    "description": f"Stun cut of 35 deg into the top-right corner at {v:.3f} m/s; the cue ball goes "
                   f"off the right and bottom rails to about [{stop[0]:.3f}, {stop[1]:.3f}] (closed "
                   f"forms with the simple rail rule) and must have a straight shot at the 2, "
                   f"placed 0.5 m from there towards the bottom-left pocket",
    "scene": scene,
    "expect": {"pocketed": ["1"], "first_hit": "1", "no_foul": True,
               "cue_ball_stops_in": {"straight_shot_at": "2", "into_pocket": "bottom-left"}},
})
simple_rails = dict(scene)
simple_rails["physics"] = {"cushion": {"model": "simple",
                                       "simple_restitution": RAIL_RESTITUTION}}
cases.append({
    "name": "two-rail-position-simple-rails",
    "description": "The same shot on rails that follow the simple rule, the one the derivation "
                   "uses: the cue ball must stop within "
                   f"{POSITION_RADIUS_M} m of the derived point",
    "scene": simple_rails,
    "expect": {"pocketed": ["1"], "no_foul": True,
               "cue_ball_stops_in": {"circle": [r4(stop[0]), r4(stop[1]), POSITION_RADIUS_M]}},
})

suite = {
    "description": "Positional drills (docs/positional.md): expected regions from closed forms "
                   "(tools/positional_suite.py), not from the simulator",
    "cases": cases,
}
assets = sys.argv[1] if len(sys.argv) == 2 else sys.exit("usage: positional_suite.py ASSETS_DIR")
for name, scene in shipped_scenes.items():
    with open(os.path.join(assets, "scenes", name + ".json"), "w") as f:
        f.write("{\n" + ",\n".join(f"  {json.dumps(k)}: {json.dumps(v)}" for k, v in scene.items())
                + "\n}\n")
with open(os.path.join(assets, "suites", "positional-drills.json"), "w") as f:
    f.write(json.dumps(suite, indent=2) + "\n")
print(json.dumps(notes, indent=2))
