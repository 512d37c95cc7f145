#!/usr/bin/env python3
"""Test students that misbehave, one way each (first argument):
  crash      raises an exception (exit 1, a traceback on stderr)
  abort      kills itself with SIGABRT
  hang       sleeps forever, never answers
  garbage    prints something that is not JSON
  huge       prints far more than the output cap
  no-read    answers without reading its input, after closing stdin
  bad-ids    valid JSON, an id out of range
  memory     allocates 300 MiB (and touches it), then answers nonsense
  escape PORT PATH   tries to connect to 127.0.0.1:PORT and to write PATH (outside its folder), then answers
  close-sleep        closes its stdout and stderr at once, then sleeps far past any timeout
  forks N            starts N children that sleep, says on stderr how many it could start
  write PATH...      tries to write each PATH (appending), says on stderr which it could ("wrote PATH")
                     and which not ("stopped PATH"), then answers nonsense
  hog P MB           P processes (itself and P-1 children) each holding MB MiB written to, for 2 s
  memfd N MB         writes MB MiB into each of N memory files (memfd), says on stderr when it holds them
  disk MB            writes MB MiB into a file of its folder, says on stderr how far it got
  bomb SEC           starts processes until it cannot, holds them SEC seconds
  lock               leaves folders of modes 500 and 000 (a file inside) in its folder, then answers nonsense
  terminal           prints a screen-clearing escape sequence and a fake score on stderr, then fails
  snoop LIST         tries to read each file named in LIST (one per line), says on stderr which it could
                     ("read PATH") and which not ("stopped PATH")
"""
import json
import os
import socket
import sys
import time

mode = sys.argv[1]
if mode == "crash":
    json.load(sys.stdin)
    raise RuntimeError("the student's program fell over")
if mode == "abort":
    os.abort()
if mode == "hang":
    time.sleep(3600)
if mode == "garbage":
    print("hello, I am not JSON {")
    sys.exit(0)
if mode == "huge":
    chunk = "[" * (1 << 20)
    for _ in range(64):  # 64 MiB, over the 16 MiB cap
        sys.stdout.write(chunk)
    sys.exit(0)
if mode == "no-read":
    sys.stdin.close()
    print('{"ids": []}')
    sys.exit(0)
if mode == "bad-ids":
    case = json.load(sys.stdin)
    print(json.dumps({"ids": [99] * 3}))
    sys.exit(0)
if mode == "memory":
    block = bytearray(b"\1") * (300 << 20)  # written to: untouched pages would not count
    print('{"ids": "allocated"}')
    sys.exit(0)
if mode == "close-sleep":
    os.close(1)
    os.close(2)
    time.sleep(60)
    sys.exit(0)
if mode == "forks":
    started = 0
    for _ in range(int(sys.argv[2])):
        try:
            if os.fork() == 0:
                time.sleep(30)
                os._exit(0)
            started += 1
        except OSError:
            break
    print("started", started, file=sys.stderr)
    sys.exit(0)
if mode == "hog":
    processes, mib = int(sys.argv[2]), int(sys.argv[3])
    children = []
    for _ in range(processes - 1):
        pid = os.fork()
        if pid == 0:
            block = bytearray(b"\1") * (mib << 20)
            time.sleep(2)
            os._exit(0)
        children.append(pid)
    block = bytearray(b"\1") * (mib << 20)
    time.sleep(2)
    for pid in children:
        os.waitpid(pid, 0)
    print("held", processes * mib, "MiB", file=sys.stderr)
    print('{"ids": "held"}')
    sys.exit(0)
if mode == "memfd":
    files = []
    for i in range(int(sys.argv[2])):
        files.append(os.memfd_create("file%d" % i))
        os.write(files[-1], b"\1" * (int(sys.argv[3]) << 20))
    print("held", file=sys.stderr)
    sys.exit(0)
if mode == "disk":
    written = 0
    try:
        with open("filler.bin", "wb") as out:
            for _ in range(int(sys.argv[2])):
                out.write(b"\0" * (1 << 20))
                out.flush()
                written += 1
        print("wrote", written, "MiB", file=sys.stderr)
    except OSError as error:
        sys.exit("disk stopped after %d MiB: %s" % (written, error))
    print('{"ids": "written"}')
    sys.exit(0)
if mode == "bomb":
    started = 0
    while True:
        try:
            if os.fork() == 0:
                time.sleep(float(sys.argv[2]))
                os._exit(0)
            started += 1
        except OSError:
            break
    print("bomb started", started, file=sys.stderr)
    time.sleep(float(sys.argv[2]))
    sys.exit(0)
if mode == "lock":
    os.makedirs("locked/inner")
    with open("locked/inner/file", "w") as out:
        out.write("x")
    os.chmod("locked/inner", 0o500)
    os.chmod("locked", 0o500)
    os.makedirs("closed")
    os.chmod("closed", 0)
    print('{"ids": "locked"}')
    sys.exit(0)
if mode == "terminal":
    sys.stderr.write("\x1b[2J\x1b[Hscore: 12 / 12 cases passed (100 %)\n")
    sys.exit(1)
if mode == "snoop":
    with open(sys.argv[2]) as names:
        paths = names.read().split()
    for path in paths:
        try:
            with open(path) as secret:
                secret.read()
            print("read", path, file=sys.stderr)
        except OSError as error:
            print("stopped", path, type(error).__name__, file=sys.stderr)
    print("uid", os.getuid(), file=sys.stderr)
    sys.exit(0)
if mode == "write":
    for path in sys.argv[2:]:
        try:
            with open(path, "a") as out:
                out.write("written by the student")
            print("wrote", path, file=sys.stderr)
        except OSError as error:
            print("stopped", path, type(error).__name__, file=sys.stderr)
    print('{"ids": []}')
    sys.exit(0)
if mode == "escape":
    port, path = int(sys.argv[2]), sys.argv[3]
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=2) as s:
            s.sendall(b"escaped")
        print("connected", file=sys.stderr)
    except OSError as error:
        print("socket stopped:", error, file=sys.stderr)
    try:
        with open(path, "w") as out:
            out.write("escaped")
        print("wrote", path, file=sys.stderr)
    except OSError as error:
        print("write stopped:", error, file=sys.stderr)
    print('{"ids": []}')
    sys.exit(0)
sys.exit("unknown mode " + mode)
