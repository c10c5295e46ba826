#!/usr/bin/env python3
"""tire-game --audio-log, headless (SDL_VIDEODRIVER=offscreen, SDL_AUDIODRIVER=dummy): what the log
says would be heard.

  audio_log_check.py GAME OUT_DIR drop  LEVEL_3M LEVEL_03M   a drop from 3 m hits louder than from 0.3 m
  audio_log_check.py GAME OUT_DIR rest  LEVEL                a tire resting 5 s is silent once settled
  audio_log_check.py GAME OUT_DIR voices LEVEL               never more than the voice limit at once
"""
import json
import os
import subprocess
import sys

VOICE_LIMIT = 8  # game/sound/voice_mixer.h, kMaxVoices


def run(game, out_dir, level, frames, name, press=None):
    log = os.path.join(out_dir, name + ".jsonl")
    cmd = [game, level, "--frames", str(frames), "--audio-log", log]
    if press:
        cmd += ["--press", press]
    env = dict(os.environ, SDL_VIDEODRIVER="offscreen", SDL_AUDIODRIVER="dummy")
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=300)
    print(" ".join(cmd))
    print(done.stdout.strip())
    if done.stderr.strip():
        print(done.stderr.strip())
    if done.returncode != 0:
        sys.exit(f"tire-game exited {done.returncode}")
    summary = json.loads(done.stdout.strip().splitlines()[-1])
    with open(log) as f:
        events = [json.loads(line) for line in f if line.strip()]
    return summary, events


def impacts(events):
    return [e for e in events if e["kind"] == "impact"]


def main():
    game, out_dir, mode = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(out_dir, exist_ok=True)
    if mode == "drop":
        _, high = run(game, out_dir, sys.argv[4], 120, "drop-3m")
        _, low = run(game, out_dir, sys.argv[5], 120, "drop-0.3m")
        h, l = impacts(high), impacts(low)
        if not h or not l:
            sys.exit("FAIL: a drop made no impact sound")
        print(f"first impact: 3 m gain {h[0]['gain']} pitch {h[0]['pitch']} (tick {h[0]['tick']}); "
              f"0.3 m gain {l[0]['gain']} pitch {l[0]['pitch']} (tick {l[0]['tick']})")
        if not h[0]["gain"] > l[0]["gain"]:
            sys.exit("FAIL: the drop from 3 m is not louder")
    elif mode == "rest":
        _, events = run(game, out_dir, sys.argv[4], 360, "resting")
        late = [e for e in impacts(events) if e["tick"] > 60]
        print(f"impacts: {len(impacts(events))}, after tick 60: {len(late)}")
        if late:
            sys.exit(f"FAIL: a settled tire made impact sounds: {late[:5]}")
    elif mode == "voices":
        summary, events = run(game, out_dir, sys.argv[4], 600, "voices", "right:0-599")
        mix = [e for e in events if e["kind"] == "mix"]
        playing = max((e["playing"] for e in mix), default=0)
        wanted = max((e["wanted"] for e in mix), default=0)
        print(f"events: {len(events) - len(mix)}; voices playing at most {playing} of up to {wanted} wanted; "
              f"summary max_voices {summary['sound']['max_voices']}")
        if playing > VOICE_LIMIT or summary["sound"]["max_voices"] > VOICE_LIMIT:
            sys.exit("FAIL: more voices than the limit")
        if wanted <= VOICE_LIMIT:
            sys.exit("FAIL: the limit was never needed: the test shows nothing")
    else:
        sys.exit(f"unknown mode {mode}")
    print("ok")


if __name__ == "__main__":
    main()
