"""view_dumps.py: takes QEMU monitor `screendump`s of the ramfb view while a
frame renders, then checks them against the finished image.  It only talks
to the monitor of a QEMU that links1 started; it never starts QEMU.

usage: view_dumps.py MONITOR_SOCKET DUMP_DIR FINISHED.ppm
           dumps one after another until a dump equals FINISHED.ppm (the
           frame is finished) or QEMU goes; keeps each dump that differs
           from the one before
       view_dumps.py --check DUMP_DIR FINAL.ppm     (prints PASS/FAIL lines)

Each dump is taken with the emulation stopped, and the board runs only a
short slice between two (grab), so some dumps show the frame part done on
a fast host or a loaded one.  The frame memory shows only finished pixels,
so whatever the timing, every
dump must be the final image with some pixels not yet written (black): a lit
pixel that differs from the final image is a fault of the view, the lit
count never shrinks, some dump shows the frame part done, and the last dump
is the final image.
"""
import os
import socket
import sys
import time

WAIT_FOR_SOCKET_S = 60
RUN_SLICE_S = 0.005  # the board runs this long between two dumps


def read_to_prompt(s):
    got = b""
    while not got.endswith(b"(qemu) "):
        chunk = s.recv(4096)
        if not chunk:
            raise ConnectionError("the monitor closed")
        got += chunk
    return got


def monitor_commands(path, lines):
    """Runs monitor commands one after another on one connection and
    returns when QEMU has done the last (its prompt is back)."""
    s = socket.socket(socket.AF_UNIX)
    try:
        s.settimeout(60)
        s.connect(path)
        read_to_prompt(s)  # the banner
        for line in lines:
            s.sendall(line.encode() + b"\n")
            read_to_prompt(s)
    finally:
        s.close()


def grab(path, out_dir, finished_path):
    """Each dump is taken with the emulation stopped, and between two dumps
    the board runs for RUN_SLICE_S only: a frame of emulated work takes
    many slices however fast or loaded the host is, so dumps of a partly
    rendered frame come whatever the timing."""
    finished = read_ppm(finished_path)
    deadline = time.time() + WAIT_FOR_SOCKET_S
    while not os.path.exists(path):
        if time.time() > deadline:
            return
        time.sleep(0.05)
    n, last = 0, None
    target = os.path.join(out_dir, "grab.ppm")
    while True:
        try:
            monitor_commands(path, ["stop", "screendump " + target, "cont"])
        except OSError:
            return  # QEMU has gone: the run is over
        time.sleep(RUN_SLICE_S)
        try:
            with open(target, "rb") as f:
                data = f.read()
        except OSError:
            continue  # nothing shown yet (before the firmware set up ramfb)
        if data != last:
            os.rename(target, os.path.join(out_dir, "dump-%05d.ppm" % n))
            n += 1
            last = data
        try:
            if parse_ppm(data, target) == finished:
                return  # the frame is finished
        except (ValueError, IndexError):
            pass  # a dump cut short


def read_ppm(path):
    with open(path, "rb") as f:
        return parse_ppm(f.read(), path)


def parse_ppm(data, path):
    fields = data.split(maxsplit=4)
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError("%s: not an 8-bit P6 PPM" % path)
    w, h = int(fields[1]), int(fields[2])
    return w, h, fields[4][: w * h * 3]


def lit_mask(px, npix):
    """Bit 23 of each 24-bit pixel of the returned integer is set where the
    pixel is not black.  (v & 0x7fffff) + 0x7fffff carries into bit 23
    exactly when a low bit is set, and never out of the pixel."""
    low = int.from_bytes(b"\x7f\xff\xff" * npix, "big")
    high = int.from_bytes(b"\x80\x00\x00" * npix, "big")
    v = int.from_bytes(px, "big")
    return (((v & low) + low) | v) & high


def check(dump_dir, final_path):
    fw, fh, final = read_ppm(final_path)
    npix = fw * fh
    final_int = int.from_bytes(final, "big")
    dumps = sorted(p for p in os.listdir(dump_dir) if p.startswith("dump-"))
    framed, partial, bad, last_lit, last_px = 0, 0, [], -1, None
    for name in dumps:
        try:
            w, h, px = read_ppm(os.path.join(dump_dir, name))
        except (OSError, ValueError, IndexError):
            continue  # a dump cut short by QEMU exiting
        if (w, h) != (fw, fh) or len(px) != len(final):
            continue  # before the firmware configured ramfb
        framed += 1
        lit_bits = lit_mask(px, npix)
        diff_bits = lit_mask((int.from_bytes(px, "big") ^ final_int).to_bytes(len(px), "big"), npix)
        lit = bin(lit_bits).count("1")
        wrong = bin(lit_bits & diff_bits).count("1")
        if wrong:
            bad.append("%s: %d lit pixels differ from the final image" % (name, wrong))
        if lit < last_lit:
            bad.append("%s: %d lit pixels, fewer than the dump before (%d)" % (name, lit, last_lit))
        last_lit, last_px = lit, px
        if lit and px != final:
            partial += 1
    if framed == 0:
        print("FAIL view_shows_frame_memory: no dump of the %dx%d frame memory "
              "(%d dumps taken)" % (fw, fh, len(dumps)))
        return
    print("PASS view_shows_frame_memory (%d distinct dumps of %dx%d)" % (framed, fw, fh))
    if bad:
        print("FAIL view_pixels_are_finished_pixels: " + "; ".join(bad[:3]))
    else:
        print("PASS view_pixels_are_finished_pixels")
    if partial:
        print("PASS view_fills_while_rendering (%d dumps showed the frame part done)" % partial)
    else:
        print("FAIL view_fills_while_rendering: no dump showed a partly rendered frame")
    if last_px == final:
        print("PASS view_ends_with_final_image")
    else:
        print("FAIL view_ends_with_final_image: the last dump (%d lit pixels) is not the "
              "final image" % last_lit)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--check":
        check(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4:
        grab(sys.argv[1], sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
