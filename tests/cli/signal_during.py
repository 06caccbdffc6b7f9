#!/usr/bin/env python3
"""Runs a command with its stderr on a pseudo-terminal (so sylva-cli draws its progress bar),
waits until the bar shows STAGE at PERCENT or more and then DELAY seconds, sends SIGNAL, and exits with the command's
exit status. Prints the seconds from the signal to the exit on stdout (a figure for the docs;
tests never assert it). The signal lands at a known phase, not after a guessed sleep.
usage: signal_during.py STAGE PERCENT DELAY SIGNAL command args...
"""
import os
import pty
import re
import select
import signal
import subprocess
import sys
import time

stage, percent, delay, signame = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
master, slave = pty.openpty()
proc = subprocess.Popen(sys.argv[5:], stderr=slave, stdout=subprocess.DEVNULL)
os.close(slave)
seen, sent, reached = "", None, None
bar = re.compile(re.escape(stage) + r"\s*\[[#.]*\]\s*(\d+)%")
while proc.poll() is None:
    ready, _, _ = select.select([master], [], [], 0.05)
    if ready:
        try:
            seen += os.read(master, 4096).decode(errors="replace")
        except OSError:
            break
    if reached is None and any(int(p) >= percent for p in bar.findall(seen[-2000:])):
        reached = time.monotonic()
    if sent is None and reached is not None and time.monotonic() >= reached + delay:
        proc.send_signal(getattr(signal, signame))
        sent = time.monotonic()
status = proc.wait()
while True:  # what it wrote last (the message after the bar)
    ready, _, _ = select.select([master], [], [], 0.2)
    if not ready:
        break
    try:
        chunk = os.read(master, 4096)
    except OSError:
        break
    if not chunk:
        break
    seen += chunk.decode(errors="replace")
if sent is None:
    sys.stderr.write(f"the command ended before {stage} reached {percent}% + {delay} s:\n"
                     f"{seen[-500:]}\n")
    sys.exit(99)
print(f"{time.monotonic() - sent:.2f}")
sys.stderr.write(seen.replace("\r\n", "\n").split("\r")[-1][-300:] + "\n")
sys.exit(status if status >= 0 else 128 - status)
