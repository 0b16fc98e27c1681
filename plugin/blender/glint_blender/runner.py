"""Runs the glint CLI as a child process while the render engine reports progress and watches
for cancel.

stdout and stderr are read on two threads into one queue (a full pipe would otherwise stall glint);
the caller's thread polls every POLL_S: `progress X` lines go to on_progress, test_break() asks to
stop. Stopping sends SIGTERM (glint exits with 130 within a second, writing nothing), waits up to
KILL_AFTER_S and then kills. No Blender API is used here, so it is testable without Blender.
"""

import os
import queue
import signal
import subprocess
import threading
import time

POLL_S = 0.05
KILL_AFTER_S = 1.0


class Result:
    """What a run gave: the exit code (negative: killed by that signal), whether it was
    cancelled, glint's stderr without the progress lines, and its stdout."""

    def __init__(self, returncode, cancelled, stderr_lines, stdout_lines, pid):
        self.returncode = returncode
        self.cancelled = cancelled
        self.stderr_lines = stderr_lines
        self.stdout_lines = stdout_lines
        self.pid = pid

    @property
    def ok(self):
        return self.returncode == 0 and not self.cancelled

    def error_lines(self):
        """glint's own messages, the `error:` lines first (what the user needs to read)."""
        lines = [l for l in self.stderr_lines if l.strip()]
        errors = [i for i, l in enumerate(lines) if "error" in l.lower()]
        if errors:
            return lines[errors[0]:]
        return lines


def _pump(stream, name, q):
    try:
        for line in iter(stream.readline, ""):
            q.put((name, line.rstrip("\r\n")))
    except (OSError, ValueError):
        pass
    finally:
        q.put((name, None))


def parse_progress(line):
    """The fraction of a `progress 0.42` line, or None."""
    if not line.startswith("progress "):
        return None
    try:
        return min(1.0, max(0.0, float(line.split()[1])))
    except (IndexError, ValueError):
        return None


def run(cmd, cwd=None, on_progress=None, on_line=None, test_break=None, on_start=None,
        poll_s=POLL_S):
    """Runs cmd (a list) to completion or cancel. on_progress(fraction) for each progress line,
    on_line(stream, text) for every other line, test_break() -> True to stop glint, on_start(pid)
    once it runs. Raises OSError when cmd cannot be started."""
    proc = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, encoding="utf-8",
                            errors="replace", bufsize=1)
    if on_start:
        on_start(proc.pid)
    q = queue.Queue()
    readers = [threading.Thread(target=_pump, args=(proc.stdout, "stdout", q), daemon=True),
               threading.Thread(target=_pump, args=(proc.stderr, "stderr", q), daemon=True)]
    for t in readers:
        t.start()
    out, err = [], []
    open_streams = 2
    cancelled = False

    def drain(block_s):
        nonlocal open_streams
        deadline = time.monotonic() + block_s
        while True:
            timeout = deadline - time.monotonic()
            try:
                name, line = q.get(timeout=max(0.0, timeout)) if timeout > 0 else q.get_nowait()
            except queue.Empty:
                return
            if line is None:
                open_streams -= 1
                continue
            if name == "stderr":
                p = parse_progress(line)
                if p is not None:
                    if on_progress:
                        on_progress(p)
                    continue
                err.append(line)
            else:
                out.append(line)
            if on_line:
                on_line(name, line)

    try:
        while proc.poll() is None:
            drain(poll_s)
            if not cancelled and test_break and test_break():
                cancelled = True
                stop(proc)
    except BaseException:
        # The engine itself failed (or Python was interrupted): never leave glint running.
        stop(proc)
        raise
    # Everything glint wrote after the last poll.
    for t in readers:
        t.join(timeout=2.0)
    drain(0)
    return Result(proc.returncode, cancelled, err, out, proc.pid)


def stop(proc):
    """SIGTERM, up to KILL_AFTER_S for glint to exit, then SIGKILL. Returns the exit code."""
    if proc.poll() is not None:
        return proc.returncode
    try:
        proc.send_signal(signal.SIGTERM)
        return proc.wait(timeout=KILL_AFTER_S)
    except subprocess.TimeoutExpired:
        proc.kill()
        return proc.wait()
    except ProcessLookupError:
        return proc.wait()


def pid_alive(pid):
    """Whether a process with this pid exists and is not a zombie (for tests)."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        try:
            os.kill(pid, 0)
            return True
        except OSError:
            return False
