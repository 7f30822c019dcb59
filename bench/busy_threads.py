#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""How many of a command's threads are runnable, sampled every 5 ms while it runs.

A shared machine's load stretches a run's wall time, but not which parts of it have one thread
to run and which have two or more. From the samples this prints the share of samples with k
threads runnable, and what the CPU time would take on an idle machine of `--cores` cores: each
sample's k threads progress together, so on idle cores they take k / min(k, cores) of a thread's
time. The command's own user time (from its rusage) times that factor is the idle-machine
estimate, which lies between user time / cores and user time.

  python3 bench/busy_threads.py [--cores 2] -- COMMAND...
"""
import argparse
import collections
import os
import subprocess
import sys
import time


def runnable_threads(pid):
    count = 0
    for task in os.listdir(f"/proc/{pid}/task"):
        try:
            with open(f"/proc/{pid}/task/{task}/stat") as stat:
                text = stat.read()
        except OSError:
            continue
        if text[text.rindex(")") + 2] == "R":
            count += 1
    return count


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cores", type=int, default=2)
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("give the command after --")
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL)
    samples = collections.Counter()
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid != 0:
            break
        try:
            samples[runnable_threads(process.pid)] += 1
        except OSError:
            pass
        time.sleep(0.005)
    wall = time.monotonic() - start
    busy = {k: n for k, n in samples.items() if k > 0}
    thread_time = sum(k * n for k, n in busy.items())
    idle_time = sum(k / min(k, args.cores) * n for k, n in busy.items())
    factor = idle_time / thread_time if thread_time else 1.0
    one = busy.get(1, 0) / idle_time if idle_time else 0.0
    total = sum(samples.values()) or 1
    shares = " ".join(f"{k}:{100 * n / total:.0f}%" for k, n in sorted(samples.items()))
    print(f"wall {wall:.2f} s, user {usage.ru_utime:.2f} s; threads runnable {shares}; "
          f"idle {args.cores}-core estimate {usage.ru_utime * factor:.2f} s "
          f"(x{factor:.2f} of user), {100 * one:.0f} % of it on one thread")
    return os.waitstatus_to_exitcode(status)


if __name__ == "__main__":
    sys.exit(main())
