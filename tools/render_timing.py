"""One render's timings report: what tools/media_timing.py and tools/ab_timing.py measure."""
import json
import os
import subprocess


def render_report(binary, scene, method, size, folder, profile=None):
    """Renders SCENE (3 frames) into FOLDER and returns the --timings report as a dict."""
    timings = os.path.join(folder, "timings.json")
    cmd = [binary, "render", scene, "--method", method, "--size", size, "--frames", "3",
           "--timings", timings, "--out", os.path.join(folder, "frame.png")]
    if profile:
        cmd += ["--profile", profile]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(timings) as f:
        return json.load(f)
