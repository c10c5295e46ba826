#!/usr/bin/env python3
"""The editor in a real X window (Xvfb) driven by real mouse drags and keys (xdotool), as a level
author would: find the crate on screen, drag it 250 px to the right, save with Ctrl+S, and check
the file; drag it again, undo with Ctrl+Z, save, and check it is back; the file validates.

With NEW in place of LEVEL, builds a level from a file that does not exist, only with the mouse
and keys (O and a drag: the ground; T and a click: the tire; X and a drag: the goal; Ctrl+S), and
checks that tirectl validates it and wins it by holding right.

With VEHICLE, builds a level with a car: O and a drag: the ground; K and a click: the car (the
player); X and a drag: the goal; Ctrl+S. Then finds the car's front hub on screen by its colour,
selects the car and drags that wheel's axle handle 30 px (half a metre) to the right, saves, and
checks that only that axle moved, in the chassis' frame; the file validates and holding right wins.

usage: editor_drag_check.py TIRE_GAME TIRECTL LEVEL|NEW|VEHICLE WORKDIR
Exit 77 (ctest: skipped) when Xvfb, xdotool or ImageMagick is missing.
"""
import json
import os
import shutil
import subprocess
import sys
import time

CRATE = (214, 146, 66)  # the game's colour for dynamic props (game/renderer.cpp kDynamic)
HUB_CAP = (60, 60, 66)  # a tire's hub cap, drawn in full detail (game/renderer.cpp kHubCap)


def skip(why):
    print(f"SKIPPED: {why}")
    sys.exit(77)


def fail(why):
    print(f"FAILED: {why}")
    sys.exit(1)


def free_display():
    for n in range(90, 400):
        if not os.path.exists(f"/tmp/.X11-unix/X{n}") and not os.path.exists(f"/tmp/.X{n}-lock"):
            return f":{n}"
    fail("no free X display number")


def pixels_of(window, env, shot, colour):
    subprocess.run(["import", "-window", window, shot], env=env, check=True)
    ppm = subprocess.run(["convert", shot, "-depth", "8", "ppm:-"], env=env, check=True,
                         capture_output=True).stdout
    parts = ppm.split(maxsplit=4)
    width, height, data = int(parts[1]), int(parts[2]), parts[4]
    found = []
    for i in range(0, width * height * 3, 3):
        if data[i] == colour[0] and data[i + 1] == colour[1] and data[i + 2] == colour[2]:
            found.append(((i // 3) % width, (i // 3) // width))
    return found


def crate_pixels(window, env, shot):
    subprocess.run(["import", "-window", window, shot], env=env, check=True)
    ppm = subprocess.run(["convert", shot, "-depth", "8", "ppm:-"], env=env, check=True,
                         capture_output=True).stdout
    # P6 header: magic, width, height, maxval, each followed by whitespace.
    parts = ppm.split(maxsplit=4)
    width, height, data = int(parts[1]), int(parts[2]), parts[4]
    xs, ys = [], []
    for i in range(0, width * height * 3, 3):
        r, g, b = data[i], data[i + 1], data[i + 2]
        if abs(r - CRATE[0]) < 8 and abs(g - CRATE[1]) < 8 and abs(b - CRATE[2]) < 8:
            p = i // 3
            xs.append(p % width)
            ys.append(p // width)
    if len(xs) < 20:
        fail(f"no crate on screen ({len(xs)} crate-coloured pixels in {shot})")
    return sum(xs) / len(xs), sum(ys) / len(ys), len(xs)


def drag(window, env, x0, y0, dx, steps=25):
    def xdo(*args):
        subprocess.run(["xdotool", *args], env=env, check=True)
    xdo("mousemove", "--window", window, str(int(x0)), str(int(y0)))
    time.sleep(0.2)
    xdo("mousedown", "1")
    for i in range(1, steps + 1):
        time.sleep(0.03)
        xdo("mousemove", "--window", window, str(int(x0 + dx * i / steps)), str(int(y0)))
    time.sleep(0.2)
    xdo("mouseup", "1")
    time.sleep(0.3)


def key(window, env, chord):
    subprocess.run(["xdotool", "key", "--window", window, chord], env=env, check=True)
    time.sleep(0.5)


def crate_x(level_file):
    with open(level_file) as f:
        level = json.load(f)
    return next(p for p in level["props"] if p.get("name") == "crate")["position"][0]


def drag_box(window, env, x0, y0, x1, y1):
    def xdo(*args):
        subprocess.run(["xdotool", *args], env=env, check=True)
    xdo("mousemove", "--window", window, str(x0), str(y0))
    time.sleep(0.2)
    xdo("mousedown", "1")
    for i in range(1, 11):
        time.sleep(0.03)
        xdo("mousemove", "--window", window, str(x0 + (x1 - x0) * i // 10), str(y0 + (y1 - y0) * i // 10))
    time.sleep(0.2)
    xdo("mouseup", "1")
    time.sleep(0.3)


def build_new_level(window, env, work):
    """docs/editor.md's walkthrough: a ground, a tire on it, a goal to its right; saved."""
    key(window, env, "o")
    drag_box(window, env, 300, 500, 1000, 540)
    key(window, env, "t")
    subprocess.run(["xdotool", "mousemove", "--window", window, "350", "460"], env=env, check=True)
    time.sleep(0.3)
    subprocess.run(["xdotool", "click", "1"], env=env, check=True)
    time.sleep(0.3)
    key(window, env, "x")
    drag_box(window, env, 900, 380, 990, 500)
    key(window, env, "ctrl+s")
    subprocess.run(["import", "-window", window, os.path.join(work, "new-level.png")], env=env, check=True)


def click(window, env, x, y):
    subprocess.run(["xdotool", "mousemove", "--window", window, str(int(x)), str(int(y))], env=env, check=True)
    time.sleep(0.3)
    subprocess.run(["xdotool", "click", "1"], env=env, check=True)
    time.sleep(0.3)


def build_vehicle_level(window, env, work, tirectl, edited):
    """A ground, the editor's car on it, a goal to its right; then the front axle dragged."""
    key(window, env, "o")
    drag_box(window, env, 300, 500, 1000, 540)
    key(window, env, "k")
    click(window, env, 380, 440)
    key(window, env, "x")
    drag_box(window, env, 900, 380, 990, 500)
    key(window, env, "Escape")  # nothing selected: no handles over the hubs
    key(window, env, "ctrl+s")
    with open(edited) as f:
        placed = json.load(f)
    vehicle = placed["vehicles"][0]
    if not vehicle.get("player"):
        fail("the car placed in a level without a player is not the player")
    # The hubs: the two clusters of hub-cap pixels, left (rear) and right (front).
    hubs = pixels_of(window, env, os.path.join(work, "placed.png"), HUB_CAP)
    if len(hubs) < 10:
        fail(f"no wheel hubs on screen ({len(hubs)} hub-cap pixels)")
    middle = sum(x for x, _ in hubs) / len(hubs)
    front = [(x, y) for x, y in hubs if x > middle]
    rear = [(x, y) for x, y in hubs if x <= middle]
    fx, fy = sum(x for x, _ in front) / len(front), sum(y for _, y in front) / len(front)
    rx = sum(x for x, _ in rear) / len(rear)
    print(f"hubs on screen: rear at x {rx:.0f} px, front at ({fx:.0f}, {fy:.0f}) px")
    if not 60 < fx - rx < 90:
        fail(f"the hubs are {fx - rx:.0f} px apart, not about 72 (1.2 m at 60 px/m)")
    # Select the car by its chassis, above the middle of its wheels; drag the front axle's handle.
    click(window, env, (fx + rx) / 2, fy - 18)
    drag(window, env, fx, fy, 30, steps=10)
    key(window, env, "ctrl+s")
    subprocess.run(["import", "-window", window, os.path.join(work, "axle-dragged.png")], env=env, check=True)
    with open(edited) as f:
        dragged = json.load(f)["vehicles"][0]
    before = [w["axle"] for w in vehicle["wheels"]]
    after = [w["axle"] for w in dragged["wheels"]]
    print(f"axles before {before}, after {after}")
    if after[0] != before[0] or dragged["chassis"] != vehicle["chassis"]:
        fail("dragging the front axle moved the rear wheel or the chassis")
    if abs(after[1][0] - (before[1][0] + 0.5)) > 1e-9 or after[1][1] != before[1][1]:
        fail(f"the front axle is at {after[1]}, not half a metre right of {before[1]} in the chassis' frame")


def main():
    game, tirectl, level, work = sys.argv[1:5]
    for tool in ("Xvfb", "xdotool", "import", "convert"):
        if not shutil.which(tool):
            skip(f"{tool} is not installed (Debian: xvfb, xdotool, imagemagick)")
    os.makedirs(work, exist_ok=True)
    new = level in ("NEW", "VEHICLE")
    edited = os.path.join(work, "my-level.json" if new else "crates.json")
    if new:
        if os.path.exists(edited):
            os.remove(edited)
    else:
        shutil.copy(level, edited)
        start_x = crate_x(edited)

    display = free_display()
    xvfb = subprocess.Popen(["Xvfb", display, "-screen", "0", "1280x720x24", "-nolisten", "tcp"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    env = dict(os.environ, DISPLAY=display, SDL_VIDEODRIVER="x11", SDL_AUDIODRIVER="dummy")
    proc = None
    try:
        for _ in range(100):
            if subprocess.run(["xdotool", "getdisplaygeometry"], env=env, capture_output=True).returncode == 0:
                break
            time.sleep(0.1)
        proc = subprocess.Popen([game, "--edit", edited], env=env)
        found = subprocess.run(["xdotool", "search", "--sync", "--onlyvisible", "--name", "Soft tire editor"],
                               env=env, capture_output=True, text=True, timeout=30)
        window = found.stdout.split()[0]
        time.sleep(1.5)
        if level == "VEHICLE":
            build_vehicle_level(window, env, work, tirectl, edited)
            return finish_new(tirectl, edited)
        if new:
            build_new_level(window, env, work)
            return finish_new(tirectl, edited)

        # 1. Drag the crate 250 px to the right and save.
        x, y, n = crate_pixels(window, env, os.path.join(work, "before.png"))
        drag(window, env, x, y, 250)
        x2, _, _ = crate_pixels(window, env, os.path.join(work, "dragged.png"))
        if not 200 < x2 - x < 300:
            fail(f"the crate moved {x2 - x:.0f} px on screen, not about 250")
        key(window, env, "ctrl+s")
        moved_x = crate_x(edited)
        print(f"crate: {start_x} m at {x:.0f} px ({n} px); dragged to {x2:.0f} px; saved at {moved_x} m")
        if not moved_x > start_x + 1.0:
            fail(f"the saved crate is at x = {moved_x}, not moved right of {start_x}")

        # 2. Drag it again, undo, save: it is back where the first save left it.
        drag(window, env, x2, y, 250)
        key(window, env, "ctrl+z")
        x3, _, _ = crate_pixels(window, env, os.path.join(work, "undone.png"))
        if abs(x3 - x2) > 3:
            fail(f"after Ctrl+Z the crate is drawn at {x3:.0f} px, not back at {x2:.0f}")
        key(window, env, "ctrl+s")
        if crate_x(edited) != moved_x:
            fail(f"after Ctrl+Z and Ctrl+S the crate is at {crate_x(edited)}, not {moved_x}")
        print(f"dragged again and undone: drawn at {x3:.0f} px, saved at {crate_x(edited)} m")
    finally:
        if proc:
            proc.terminate()
            proc.wait(timeout=10)
        xvfb.terminate()
        xvfb.wait(timeout=10)

    validate(tirectl, edited)


def validate(tirectl, edited):
    check = subprocess.run([tirectl, "validate", edited], capture_output=True, text=True)
    if check.returncode != 0:
        fail("the saved level does not validate:\n" + check.stdout + check.stderr)
    print("the saved level validates")


def finish_new(tirectl, edited):
    if not os.path.exists(edited):
        fail(f"{edited} was not saved")
    with open(edited) as f:
        print(f.read())
    validate(tirectl, edited)
    run = subprocess.run([tirectl, "run", edited, "--ticks", "900", "--steer", "1"], capture_output=True, text=True)
    status = json.loads(run.stdout)["status"] if run.returncode == 0 else run.stderr
    if status != "won":
        fail(f"holding right for 15 s the level is not won: {status}")
    print("tirectl run --ticks 900 --steer 1: won")


if __name__ == "__main__":
    main()
