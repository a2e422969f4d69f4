"""External algorithms that fail, one way each, for the tests of the sweep's isolation.

    python misbehaving.py MODE POINTS OUTPUT

MODE: crash (aborts: killed by SIGABRT), hang (sleeps past any timeout), out-of-range (an
edge to a point that does not exist), malformed (a line that is not two indices), nothing
(exits normally without writing), memory (holds 400 MiB resident, then writes a valid chain);
as a reconstruction JSON: json-cut (ends inside line 3), json-out-of-range (an edge to a
point that does not exist), json-error (reports an error in the JSON).
"""
import json
import os
import sys
import time

mode, points_path, output_path = sys.argv[1:4]
count = sum(1 for line in open(points_path) if line.strip() and not line.startswith("#"))
valid_chain = "".join(f"{i} {(i + 1) % count}\n" for i in range(count))
if mode == "crash":
    os.abort()
elif mode == "hang":
    time.sleep(3600)
elif mode == "out-of-range":
    open(output_path, "w").write(f"0 1\n1 {count}\n")
elif mode == "malformed":
    open(output_path, "w").write("0 1\n1 two\n")
elif mode == "memory":
    held = bytearray(400 * 1024 * 1024)
    for page in range(0, len(held), 4096):
        held[page] = 1
    time.sleep(2)
    open(output_path, "w").write(valid_chain)
elif mode == "json-cut":
    open(output_path, "w").write('{"curve": {\n  "edges": [[0, 1],\n  [1, ')
elif mode == "json-out-of-range":
    open(output_path, "w").write(json.dumps({"curve": {"edges": [[0, 1], [1, count]]}}))
elif mode == "json-error":
    open(output_path, "w").write(json.dumps({"status": "error", "message": "too few points for this method"}))
elif mode != "nothing":
    sys.exit(f"unknown mode {mode}")
