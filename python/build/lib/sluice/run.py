"""Running a scene through the sluice command (`sluice run ... --summary-json`)."""
import json
import os
import shutil
import subprocess
import tempfile


class SluiceError(RuntimeError):
    """A run that exited with a status other than 0: exit_code 1 (the run
    failed; the last good state is in the output file), 2 (bad input:
    nothing written). summary is the run's summary dict, message the error."""

    def __init__(self, exit_code, message, summary):
        super().__init__(f"sluice exited with status {exit_code}: {message}")
        self.exit_code = exit_code
        self.message = message
        self.summary = summary


def find_binary(binary=None):
    """The sluice command: binary if given, else $SLUICE, else `sluice` on PATH."""
    candidate = binary or os.environ.get("SLUICE") or shutil.which("sluice")
    if not candidate:
        raise FileNotFoundError("the sluice command was not found: pass binary=, set $SLUICE or put sluice on PATH")
    return candidate


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (list, tuple)):
        return ", ".join(_value(x) for x in v)
    return str(v)


def _overrides(set):
    if set is None:
        return []
    items = set.items() if isinstance(set, dict) else (s.split("=", 1) for s in set)
    args = []
    for key, value in items:
        args += ["--set", f"{key}={_value(value)}"]
    return args


def run(scene, set=None, output=None, restart=None, binary=None, overwrite=False, check=True, timeout=None,
        cwd=None):
    """Runs `sluice run SCENE` and returns its summary as a dict.

    set: overrides, {"time.end": 20, "mesh.cells": [32, 32]} or ["time.end=20"];
    output: the output file (-o); restart: continue from this file's last
    checkpoint; overwrite: the output may replace a file sluice did not write.
    The dict has the keys of `sluice run --summary-json` (docs/output.md:
    status, exit_code, message, output, steps, t_reached, stop_reason, ...)
    and "stderr", what the run printed. With check (the default) an exit
    status other than 0 raises SluiceError."""
    cmd = [find_binary(binary), "run", os.fspath(scene)] + _overrides(set)
    if output is not None:
        cmd += ["-o", os.fspath(output)]
    if restart is not None:
        cmd += ["--restart", os.fspath(restart)]
    if overwrite:
        cmd.append("--overwrite")
    fd, summary_path = tempfile.mkstemp(prefix="sluice_summary_", suffix=".json")
    os.close(fd)
    try:
        cmd += ["--summary-json", summary_path]
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=timeout,
                              cwd=cwd)
        try:
            with open(summary_path, encoding="utf-8") as f:
                summary = json.load(f)
        except (OSError, ValueError):
            summary = {"status": "failed", "exit_code": proc.returncode, "message": proc.stderr.strip()}
    finally:
        os.unlink(summary_path)
    summary["stderr"] = proc.stderr
    if summary.get("output") and cwd is not None and not os.path.isabs(summary["output"]):
        summary["output"] = os.path.join(cwd, summary["output"])
    if check and proc.returncode != 0:
        raise SluiceError(proc.returncode, summary.get("message") or proc.stderr.strip(), summary)
    return summary
