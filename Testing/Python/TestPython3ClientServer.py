"""Client-server: pvpython connected to `mpiexec -np 2 pvserver` on localhost runs the
one-step BoolSurf filter (ClientServerPipeline.py) and fetches the same region as a builtin
session: triangles, arrangement cells, boundary points, area. Each process has a time limit.
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
script = os.path.join(source_dir, "Testing", "Python", "ClientServerPipeline.py")
tools = {name: shutil.which(name) for name in ("mpiexec", "pvserver", "pvpython")}
if not all(tools.values()):
    print("missing %s: nothing to test" % [k for k, v in tools.items() if not v])
    sys.exit(0)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
out = scratch.folder("boolsurf-cs-")


def client(json_path, server=None):
    command = [tools["pvpython"], script, "--json", json_path]
    if server:
        command += ["--server", server]
    done = subprocess.run(command, env=env, timeout=240, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    if done.returncode != 0:
        print(done.stdout)
        raise SystemExit("pvpython %s failed" % ("connected to " + server if server else "builtin"))
    with open(json_path) as f:
        return json.load(f)


builtin = client(os.path.join(out, "builtin.json"))
# Port 0 is not allowed by pvserver: take a free one from the system, then give it to pvserver.
import socket  # noqa: E402
with socket.socket() as s:
    s.bind(("localhost", 0))
    port = s.getsockname()[1]
server = subprocess.Popen([tools["mpiexec"], "-np", "2", tools["pvserver"],
                           "--server-port=%d" % port], env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, start_new_session=True)
try:
    # pvserver says when it listens.
    for line in server.stdout:
        if re.search(r"Accepting connection", line):
            break
    else:
        raise SystemExit("pvserver stopped before accepting connections")
    remote = client(os.path.join(out, "remote.json"), "localhost:%d" % port)
finally:
    os.killpg(server.pid, signal.SIGKILL)
    server.wait()
print("builtin:", builtin)
print("pvserver on 2 ranks:", remote)
assert remote["ranks"] == 2, remote
assert builtin["triangles"] > 0, builtin
for key in ("triangles", "cells", "boundary_points"):
    assert remote[key] == builtin[key], (key, remote, builtin)
assert abs(remote["area"] - builtin["area"]) <= 1e-9 * builtin["area"], (remote, builtin)
shutil.rmtree(out, ignore_errors=True)
