#!/usr/bin/env python3
"""dashbed_sync.py: robots go on from a synchronisation point only once all of its robots
reached it; a point out of order is refused."""
import json
import pathlib
import socket
import subprocess
import sys
import tempfile
import threading

server_script = pathlib.Path(sys.argv[1])
points = [
    {"index": 0, "t": 0.0, "robots": ["r0", "r1", "r2"], "why": "start"},
    {"index": 1, "t": 4.0, "robots": ["r0", "r1"], "why": "handoff cube_0 r0 -> r1"},
]
with tempfile.TemporaryDirectory() as tmp:
    sync_json = pathlib.Path(tmp) / "sync.json"
    sync_json.write_text(json.dumps(points))
    server = subprocess.Popen([sys.executable, str(server_script), str(sync_json), "--host", "127.0.0.1", "--port", "0"],
                              stdout=subprocess.PIPE, text=True)
    try:
        port = int(server.stdout.readline().strip().rsplit(":", 1)[1])
        clients = {r: socket.create_connection(("127.0.0.1", port), timeout=10) for r in ("r0", "r1", "r2")}
        replies = {}

        def reach(robot, index):
            clients[robot].sendall(f"{robot} {index}\n".encode())
            replies[(robot, index)] = clients[robot].makefile().readline().strip()

        # r0 and r1 reach the start; nobody goes on until r2 does
        waiting = [threading.Thread(target=reach, args=(r, 0)) for r in ("r0", "r1")]
        for t in waiting:
            t.start()
        for t in waiting:
            t.join(0.5)
        assert not replies, f"went on before every robot reached the start: {replies}"
        reach("r2", 0)
        for t in waiting:
            t.join(10)
        assert all(replies[(r, 0)] == "(0)" for r in ("r0", "r1", "r2")), replies
        # r2 takes no part in point 1: refused; r0 and r1 go on together
        reach("r2", 1)
        assert replies[("r2", 1)] == "(-1)", replies
        pair = [threading.Thread(target=reach, args=(r, 1)) for r in ("r0", "r1")]
        for t in pair:
            t.start()
        for t in pair:
            t.join(10)
        assert replies[("r0", 1)] == "(1)" and replies[("r1", 1)] == "(1)", replies
        # a point already passed is refused
        reach("r0", 0)
        assert replies[("r0", 0)] == "(-1)", replies
        print("dashbed_sync: every check passed")
    finally:
        server.terminate()
        server.wait(10)
