"""Running a pvserver for a test and checking a session's region against the one-rank answer
(TestPython3PvserverSession.py, GuiPvserverSession.py; the session itself is
PvserverSessionPipeline.py).

pvserver runs in a session of its own under `timeout`: the test stops it (mpiexec, then every
process left in that session) when it ends or fails, and `timeout` stops it if the test itself
was killed first.
"""
import os
import queue
import re
import shutil
import signal
import socket
import subprocess
import threading
import time

# The longest a pvserver may live: past this, `timeout` stops it even if the test that started
# it was killed.
SERVER_LIFETIME = 600
# The longest mpiexec may take until pvserver listens (3 ranks on 2 busy cores).
STARTUP = 120


def mpi_env():
    """The environment for mpiexec: as root, oversubscribed (3 ranks on 2 cores), and without
    the variables of a singleton MPI that pvpython may have started (they mislead mpiexec)."""
    env = {k: v for k, v in os.environ.items() if not re.match(r"(OMPI_|PMIX_|OPAL_)", k)}
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    return env


def missing_tools(names):
    return [name for name in names if not shutil.which(name)]


def free_port():
    """A port nobody listens on now (pvserver refuses port 0: take one from the system)."""
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


class PvServer:
    """`mpiexec -np ranks pvserver` on a free port, listening once the context is entered;
    stopped (every process of its session) when it is left. A port taken between our probe and
    pvserver's bind, or a slow start, gets one more try on another port."""

    def __init__(self, ranks, tries=2):
        self.ranks = ranks
        self.tries = tries
        self.process = None
        self.port = None
        self.log = []

    def __enter__(self):
        for _ in range(self.tries):
            self.port = free_port()
            if self._start():
                return self
            self.stop()
        raise RuntimeError("pvserver on %d ranks did not listen (%d tries):\n%s"
                           % (self.ranks, self.tries, "".join(self.log[-40:])))

    def __exit__(self, *exc):
        self.stop()
        return False

    @property
    def url(self):
        return "cs://localhost:%d" % self.port

    def _start(self):
        command = [shutil.which("mpiexec"), "-np", str(self.ranks), shutil.which("pvserver"),
                   "--server-port=%d" % self.port]
        if shutil.which("timeout"):
            command = [shutil.which("timeout"), "--kill-after=10", str(SERVER_LIFETIME)] + command
        self.process = subprocess.Popen(command, env=mpi_env(), stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True,
                                        start_new_session=True)
        lines = queue.Queue()

        def read():
            for line in self.process.stdout:
                lines.put(line)
            lines.put(None)

        threading.Thread(target=read, daemon=True).start()
        deadline = time.monotonic() + STARTUP
        while time.monotonic() < deadline:
            try:
                line = lines.get(timeout=max(0.1, deadline - time.monotonic()))
            except queue.Empty:
                break
            if line is None:
                return False  # mpiexec ended: the port was taken, or pvserver failed
            self.log.append(line)
            # pvserver says when it listens.
            if "Accepting connection" in line:
                # Keep draining its output so that a chatty server never blocks on a full pipe.
                threading.Thread(target=self._drain, args=(lines,), daemon=True).start()
                return True
        return False

    def _drain(self, lines):
        while True:
            line = lines.get()
            if line is None:
                return
            self.log.append(line)

    def stop(self):
        """mpiexec forwards a SIGTERM to the ranks and waits for them; whatever is left after
        that (Open MPI puts each rank in a process group of its own, but in our session) is
        killed."""
        if self.process is None:
            return
        if self.process.poll() is None:
            os.kill(self.process.pid, signal.SIGTERM)  # `timeout` passes it on to mpiexec
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                pass
        for pid in session_processes(self.process.pid):
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self.process.wait()
        # Let the killed ranks go, so that the next test starts on an idle machine.
        deadline = time.monotonic() + 10
        while session_processes(self.process.pid) and time.monotonic() < deadline:
            time.sleep(0.2)
        self.process = None


def session_processes(session):
    """The processes of the session whose leader is `session` (a process we started with
    start_new_session), from /proc."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                stat = f.read()
        except OSError:
            continue
        # pid (comm) state ppid pgrp session ...: comm may hold spaces, so split after it.
        fields = stat[stat.rindex(")") + 2:].split()
        if int(fields[3]) == session:
            found.append(int(entry))
    return found

def same_region(got, expected, where, failures):
    """The same region per SourceTriangle: the same triangles in each, the same area to
    1e-12."""
    a, b = got["by_source"], expected["by_source"]
    if a.keys() != b.keys():
        failures.append("%s: other source triangles: %s" % (where, sorted(set(a) ^ set(b))[:10]))
        return
    for source in a:
        if a[source][0] != b[source][0] or abs(a[source][1] - b[source][1]) > 1e-12:
            failures.append("%s: source triangle %s: %s, one rank %s"
                            % (where, source, a[source], b[source]))
            return
    if got["triangles"] != expected["triangles"]:
        failures.append("%s: %d triangles, one rank %d" % (where, got["triangles"],
                                                           expected["triangles"]))


def check_session(remote, serial, ranks, failures):
    """A session on `ranks` pvserver ranks (`remote`) against the builtin one (`serial`)."""
    if remote["ranks"] != ranks:
        failures.append("the session has %s ranks, not %d" % (remote["ranks"], ranks))
    # The redistributed surface lies on every rank.
    held = remote["surface"]["held"]
    if len(held) != ranks or max(held.values()) >= remote["surface"]["triangles"]:
        failures.append("the surface is not split across the %d ranks: %s" % (ranks, held))
    # The curve editor's exact points name triangles by global id: the one-rank drawing.
    if remote["drawing"] != serial["drawing"]:
        failures.append("the drawing's exact points differ from the one-rank drawing's")
    region = remote["region"]
    if "ArrangementOnPieces" in serial["region"]["fields"] or \
            "ArrangementOnPieces" not in region["fields"]:
        failures.append("the region was not computed on the pieces: fields %s" % region["fields"])
    # Each rank holds its part of the region: at least two hold some, none holds it all.
    held = region["held"]
    if len(held) < 2 or max(held.values()) >= region["triangles"]:
        failures.append("the region is not held in parts by the ranks: %s" % held)
    if serial["region"]["triangles"] <= 20:
        failures.append("the one-rank region is too small: %d triangles"
                        % serial["region"]["triangles"])
    same_region(region, serial["region"], "the region on %d ranks" % ranks, failures)
    # The screenshot shows the region (its flat color) on the surface.
    if remote["region_pixels"] < 1000:
        failures.append("the screenshot shows %d pixels of the region" % remote["region_pixels"])
    if not remote["rendered_on_server"]:
        failures.append("the view was rendered on the client, not on the server's ranks")
    # Save Data wrote a piece per rank holding part of the region (ParaView's writer leaves
    # out empty pieces); read back in the same session on the ranks, it is the same region,
    # in pieces of the same sizes.
    written = ["region_%s.vtp" % rank for rank in sorted(held, key=int)]
    if remote["pvtp_pieces"] != written:
        failures.append("Save Data wrote %s, not %s (a piece per rank holding part of the "
                        "region)" % (remote["pvtp_pieces"], written))
    back = remote["read_back"]
    same_region(back, serial["region"], "the .pvtp read back on %d ranks" % ranks, failures)
    if sorted(back["held"].values()) != sorted(held.values()):
        failures.append("the .pvtp read back lies on the ranks as %s, the region as %s"
                        % (back["held"], held))
    # The one-step filter: its region on the pieces, held in parts, the one-rank region (and
    # the one-rank one-step region), rendered on the server with as many pixels as the chain's.
    one_step = remote["one_step"]
    if "ArrangementOnPieces" not in one_step["fields"]:
        failures.append("the one-step region was not computed on the pieces: fields %s"
                        % one_step["fields"])
    if len(one_step["held"]) < 2 or max(one_step["held"].values()) >= one_step["triangles"]:
        failures.append("the one-step region is not held in parts by the ranks: %s"
                        % one_step["held"])
    same_region(one_step, serial["region"], "the one-step region on %d ranks" % ranks, failures)
    same_region(serial["one_step"], serial["region"], "the one-step region on one rank",
                failures)
    if not remote["one_step_rendered_on_server"]:
        failures.append("the one-step region was rendered on the client, not on the server")
    if abs(remote["one_step_pixels"] - remote["region_covered"]) > 0.01 * remote["region_covered"]:
        failures.append("the screenshot shows %d pixels of the one-step region, %d of the "
                        "chain's" % (remote["one_step_pixels"], remote["region_covered"]))

# Open MPI's words when a client's MPI_Init could not start its local daemon (seen once with
# other MPI jobs starting at the same time on the machine): the client never ran, run it again.
MPI_INIT_FAILED = "Unable to start a daemon on the local node"


def run_client(command, timeout, what, tries=2):
    """Runs a client (pvpython, paraview) in its own process group, all of it stopped after
    `timeout` seconds (by `timeout` as well, should the test be killed first); returns its
    output, raises naming `what` when it fails. A client whose MPI could not start is run
    again (up to `tries` times)."""
    for attempt in range(1, tries + 1):
        try:
            return run_client_once(command, timeout, what)
        except RuntimeError as error:
            if attempt == tries or MPI_INIT_FAILED not in str(error):
                raise
            print("%s: MPI did not start, once more" % what)


def run_client_once(command, timeout, what):
    if shutil.which("timeout"):
        command = [shutil.which("timeout"), "--kill-after=10", str(timeout + 30)] + command
    process = subprocess.Popen(command, env=mpi_env(), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        output, _ = process.communicate()
        raise RuntimeError("%s: no answer within %d s\n%s" % (what, timeout, output[-4000:]))
    if process.returncode != 0:
        raise RuntimeError("%s failed (exit code %d)\n%s" % (what, process.returncode,
                                                             output[-4000:]))
    return output
