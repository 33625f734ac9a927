#!/usr/bin/env python3
"""Synchronisation server for the URScript programs of `dashbed export --to urscript`.

Each robot's program connects, and at each synchronisation point K of sync.json sends the line
"ROBOT K". Once every robot of point K has sent it, each gets "(K)" back and goes on. A robot
that sends a point out of order, or that is not one of the point's robots, gets "(-1)" and its
program halts.

    python3 dashbed_sync.py OUT/sync.json [--host 0.0.0.0] [--port 30700]
"""
import argparse
import json
import socketserver
import threading


class Points:
    """Who has reached which synchronisation point."""

    def __init__(self, points):
        self.robots = {p["index"]: set(p["robots"]) for p in points}
        self.next = {}  # robot -> the index of the next point it takes part in
        for index in sorted(self.robots):
            for robot in self.robots[index]:
                self.next.setdefault(robot, [])
                self.next[robot].append(index)
        self.arrived = {index: set() for index in self.robots}
        self.lock = threading.Condition()

    def reach(self, robot, index):
        """Blocks until every robot of point `index` has reached it; False for a wrong point."""
        with self.lock:
            expected = self.next.get(robot, [])
            if not expected or expected[0] != index:
                return False
            expected.pop(0)
            self.arrived[index].add(robot)
            self.lock.notify_all()
            self.lock.wait_for(lambda: self.arrived[index] == self.robots[index])
            return True


class Handler(socketserver.StreamRequestHandler):
    def handle(self):
        for raw in self.rfile:
            words = raw.decode("ascii", "replace").split()
            ok = len(words) == 2 and words[1].isdigit() and self.server.points.reach(words[0], int(words[1]))
            reply = f"({words[1]})\n" if ok else "(-1)\n"
            print(f"{' '.join(words)}: {'go' if ok else 'refused'}", flush=True)
            self.wfile.write(reply.encode("ascii"))


class Server(socketserver.ThreadingTCPServer):
    daemon_threads = True
    allow_reuse_address = True


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sync_json", help="sync.json written by dashbed export --to urscript")
    parser.add_argument("--host", default="0.0.0.0")
    parser.add_argument("--port", type=int, default=30700, help="0: any free port (printed)")
    args = parser.parse_args()
    with open(args.sync_json, encoding="utf-8") as f:
        points = json.load(f)
    with Server((args.host, args.port), Handler) as server:
        server.points = Points(points)
        host, port = server.server_address[:2]
        print(f"dashbed_sync: {len(points)} synchronisation points, listening on {host}:{port}", flush=True)
        server.serve_forever()


if __name__ == "__main__":
    main()
