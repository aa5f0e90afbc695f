"""Helpers of the benchmark and tutorial scripts that drive OpenFOAM cases:
run an application with its log, set a top-level dictionary entry.
etc/bashrc puts this folder on PYTHONPATH."""
import os
import re
import subprocess
import sys


def run_logged(cmd, cwd, log):
    """Run cmd in cwd with stdout and stderr into cwd/log; on failure, exit
    with the log's tail."""
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode:
        tail = open(os.path.join(cwd, log)).read()[-3000:]
        sys.exit(f"{' '.join(cmd)} failed in {cwd} (see {log}):\n{tail}")


def set_entry(path, key, value):
    """Replace the first top-level 'key ...;' line of a dictionary file."""
    s = open(path).read()
    s, n = re.subn(rf"^{key}\s+.*?;", f"{key} {value};", s, count=1, flags=re.M)
    assert n == 1, (path, key)
    open(path, "w").write(s)
