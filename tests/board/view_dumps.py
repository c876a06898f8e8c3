"""view_dumps.py: takes QEMU monitor `screendump`s of the ramfb view while a
frame renders, then checks them against the finished image.

usage: view_dumps.py MONITOR_SOCKET DUMP_DIR            (grab until QEMU goes)
       view_dumps.py --check DUMP_DIR FINAL.ppm          (print PASS/FAIL lines)

The frame memory shows only finished pixels, so every dump must be the final
image with some pixels not yet written (black): a lit pixel that differs from
the final image is a fault of the view, and the lit count must never shrink.
"""
import os
import socket
import sys
import time

GRAB_PERIOD_S = 0.25
WAIT_FOR_SOCKET_S = 30


def grab(path, out_dir):
    deadline = time.time() + WAIT_FOR_SOCKET_S
    while not os.path.exists(path):
        if time.time() > deadline:
            return
        time.sleep(0.05)
    n = 0
    while True:
        try:
            s = socket.socket(socket.AF_UNIX)
            s.connect(path)
            s.settimeout(5)
            s.recv(4096)  # the monitor's banner and prompt
            target = os.path.join(out_dir, "dump-%03d.ppm" % n)
            s.sendall(b"screendump " + target.encode() + b"\n")
            s.recv(4096)
            s.close()
        except OSError:
            return  # QEMU has gone: the run is over
        n += 1
        time.sleep(GRAB_PERIOD_S)


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields = data.split(maxsplit=4)
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError("%s: not an 8-bit P6 PPM" % path)
    w, h = int(fields[1]), int(fields[2])
    return w, h, fields[4][: w * h * 3]


def check(dump_dir, final_path):
    fw, fh, final = read_ppm(final_path)
    dumps = sorted(p for p in os.listdir(dump_dir) if p.startswith("dump-"))
    framed, partial, bad, last_lit = 0, 0, [], -1
    for name in dumps:
        try:
            w, h, px = read_ppm(os.path.join(dump_dir, name))
        except (OSError, ValueError, IndexError):
            continue  # a dump cut short by QEMU exiting
        if (w, h) != (fw, fh) or len(px) != len(final):
            continue  # before the firmware configured ramfb
        framed += 1
        lit = wrong = 0
        for i in range(0, len(px), 3):
            p = px[i:i + 3]
            if p != b"\0\0\0":
                lit += 1
                wrong += p != final[i:i + 3]
        if wrong:
            bad.append("%s: %d lit pixels differ from the final image" % (name, wrong))
        if lit < last_lit:
            bad.append("%s: %d lit pixels, fewer than the dump before (%d)" % (name, lit, last_lit))
        last_lit = lit
        if 0 < lit < fw * fh * 0.95:
            partial += 1
    if framed == 0:
        print("FAIL view_shows_frame_memory: no dump of the %dx%d frame memory "
              "(%d dumps taken)" % (fw, fh, len(dumps)))
        return
    print("PASS view_shows_frame_memory (%d dumps of %dx%d)" % (framed, fw, fh))
    if bad:
        print("FAIL view_pixels_are_finished_pixels: " + "; ".join(bad[:3]))
    else:
        print("PASS view_pixels_are_finished_pixels")
    if partial:
        print("PASS view_fills_while_rendering (%d dumps caught the frame part done)" % partial)
    else:
        print("FAIL view_fills_while_rendering: no dump showed a partly rendered frame")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--check":
        check(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3:
        grab(sys.argv[1], sys.argv[2])
    else:
        sys.exit(__doc__)
