#!/usr/bin/env python3
"""fw_board.py: firmware board checks that need frames the links1 tool never
sends on purpose: damaged frames, unknown commands, malformed payloads,
frames out of place, and every kind of injected fault.

Boots QEMU itself with the UART on one end of a socketpair, speaks the
host-link framing of proto/hostlink.h, and prints one "PASS name" or
"FAIL name: why" line per check (counted by tests/run.sh).

usage: fw_board.py ELF SMP"""
import os
import socket
import struct
import subprocess
import sys
import tempfile
import time
import zlib

LINK_LOG, LINK_HELLO, LINK_FAULT, LINK_CMD, LINK_RESULT, LINK_DATA, LINK_ACK = range(1, 8)
CMD_STATUS, CMD_LINE_PING, CMD_LINE_STRESS, CMD_FAULT_INJECT = 1, 2, 4, 7
FAULT_UNDEF, FAULT_PREFETCH, FAULT_DATA, FAULT_PANIC = 1, 2, 3, 4
LOCK_TWICE, UNLOCK_FREE = 0x10, 0x11  # FAULT_INJECT_* of proto/hostlink.h
ERR_UNKNOWN_CMD, ERR_BAD_ARGS, ERR_BAD_FRAME, ERR_TIMEOUT, ERR_PROTOCOL = -1, -2, -3, -4, -6
UNMAPPED_VIRT = 0x80000000  # kernel/memlayout.h: the block left unmapped
WAIT_S = 30


class Board:
    def __init__(self, elf, smp, ram_mb=512):
        self.sock, theirs = socket.socketpair()
        # QEMU's own messages go to a file, shown only when the board dies.
        self.qemu_err = tempfile.TemporaryFile()
        self.qemu = subprocess.Popen(
            ["qemu-system-arm", "-M", "virt,gic-version=3", "-cpu", "cortex-a15",
             "-smp", str(smp), "-m", str(ram_mb), "-nographic", "-monitor", "none",
             "-kernel", elf, "-chardev", "socket,id=link,fd=%d" % theirs.fileno(),
             "-serial", "chardev:link"],
            pass_fds=[theirs.fileno()], stdout=subprocess.DEVNULL,
            stderr=self.qemu_err)
        theirs.close()
        self.buf = b""
        self.seq = 0
        self.faults = []
        self.logs = []
        self.hellos = set()

    def send_raw(self, data):
        self.sock.sendall(data)

    def frame(self, ftype, payload, flags=0, crc_fix=0):
        head = bytes([ftype, flags]) + struct.pack("<HH", self.seq, len(payload))
        self.seq = (self.seq + 1) & 0xFFFF
        crc = (zlib.crc32(head + payload) ^ crc_fix) & 0xFFFFFFFF
        return b"L1" + head + payload + struct.pack("<I", crc)

    def send(self, ftype, payload, **kw):
        self.send_raw(self.frame(ftype, payload, **kw))

    def next_frame(self, deadline):
        """Next board frame (type, payload); LOG/HELLO/FAULT are recorded."""
        while True:
            i = self.buf.find(b"L1")
            if i >= 0 and len(self.buf) >= i + 8:
                n = struct.unpack("<H", self.buf[i + 6:i + 8])[0]
                if len(self.buf) >= i + 12 + n:
                    body = self.buf[i + 2:i + 8 + n]
                    crc = struct.unpack("<I", self.buf[i + 8 + n:i + 12 + n])[0]
                    self.buf = self.buf[i + 12 + n:]
                    if zlib.crc32(body) & 0xFFFFFFFF != crc:
                        raise RuntimeError("board sent a frame with a bad CRC")
                    ftype, payload = body[0], body[6:]
                    if ftype == LINK_LOG:
                        self.logs.append(payload.decode(errors="replace"))
                        print("    log:", self.logs[-1])
                    elif ftype == LINK_HELLO:
                        self.hellos.add(struct.unpack("<H", payload[:2])[0])
                    elif ftype == LINK_FAULT:
                        self.faults.append(struct.unpack("<HBBIII", payload[:16]) +
                                           (payload[16:].decode(errors="replace"),))
                    return ftype, payload
            left = deadline - time.time()
            if left <= 0:
                raise TimeoutError("no frame from the board in time")
            self.sock.settimeout(left)
            data = self.sock.recv(65536)
            if not data:
                self.qemu_err.seek(0)
                raise EOFError("the board's link closed (QEMU exited): %s"
                               % self.qemu_err.read().decode(errors="replace").strip())
            self.buf += data

    def result(self, timeout=WAIT_S):
        """Waits for the next LINK_RESULT: (cmd, status, rest)."""
        deadline = time.time() + timeout
        while True:
            ftype, p = self.next_frame(deadline)
            if ftype == LINK_RESULT:
                cmd, status = struct.unpack("<Hh", p[:4])
                return cmd, status, p[4:]

    def wait_hellos(self, n):
        deadline = time.time() + 60
        while len(self.hellos) < n:
            self.next_frame(deadline)

    def wait_faults(self, n, timeout=WAIT_S):
        deadline = time.time() + timeout
        while len(self.faults) < n:
            self.next_frame(deadline)

    def cmd(self, code, args=b"", timeout=WAIT_S):
        self.send(LINK_CMD, struct.pack("<H", code) + args)
        return self.result(timeout)

    def stop(self):
        self.qemu.terminate()
        try:
            self.qemu.wait(5)
        except subprocess.TimeoutExpired:
            self.qemu.kill()


def check(name, ok, why):
    print(("PASS %s" % name) if ok else ("FAIL %s: %s" % (name, why)))
    sys.stdout.flush()


def text(rest):
    return rest.decode(errors="replace")


def bad_input_checks(b, smp):
    # A frame whose CRC is wrong: dropped and reported, cmd 0.
    b.send(LINK_CMD, struct.pack("<H", CMD_STATUS), crc_fix=0x1)
    cmd, st, rest = b.result()
    check("fw_bad_crc_reported", cmd == 0 and st == ERR_BAD_FRAME and "bad CRC 1" in text(rest),
          "got cmd %d status %d '%s'" % (cmd, st, text(rest)))
    # A header announcing more than LINK_MAX_PAYLOAD, then junk.
    b.send_raw(b"L1\x04\x00\x00\x00\xff\xff" + b"\x00" * 16)
    cmd, st, rest = b.result()
    check("fw_bad_length_reported", st == ERR_BAD_FRAME and "bad length 1" in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    cmd, st, rest = b.cmd(99)
    check("fw_unknown_command", cmd == 99 and st == ERR_UNKNOWN_CMD and "unknown command 99" in text(rest),
          "got cmd %d status %d '%s'" % (cmd, st, text(rest)))
    b.send(LINK_CMD, b"\x01")
    cmd, st, rest = b.result()
    check("fw_cmd_without_number", st == ERR_BAD_ARGS and "no command number" in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    cmd, st, rest = b.cmd(CMD_LINE_STRESS, b"\x01")
    check("fw_stress_short_args", cmd == CMD_LINE_STRESS and st == ERR_BAD_ARGS and "needs u32" in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    cmd, st, rest = b.cmd(CMD_LINE_STRESS, struct.pack("<I", 0))
    check("fw_stress_zero_mib", st == ERR_BAD_ARGS and "outside" in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    cmd, st, rest = b.cmd(CMD_FAULT_INJECT, struct.pack("<HB", smp, FAULT_UNDEF))
    check("fw_fault_core_out_of_range", st == ERR_BAD_ARGS and "out of range" in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    b.send(LINK_DATA, b"stray")
    cmd, st, rest = b.result()
    check("fw_data_outside_transfer", st == ERR_PROTOCOL and "outside a transfer" in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    cmd, st, rest = b.cmd(CMD_STATUS)
    ncores, reported, halted = struct.unpack("<HHH", rest[:6]) if st == 0 else (0, 0, 0)
    check("fw_runs_after_bad_input", st == 0 and ncores == smp and reported == smp and halted == 0,
          "status %d, %d cores, %d reported, %d halted" % (st, ncores, reported, halted))


def fault_checks(b, smp):
    """Data abort, prefetch abort, panic and both spinlock misuses on five
    NCs, each reported as what it is; then the rest still answer."""
    # (core, injected kind, reported kind, label, text the report must hold)
    cases = [(2, FAULT_DATA, FAULT_DATA, "data", "data abort"),
             (3, FAULT_PREFETCH, FAULT_PREFETCH, "prefetch", "prefetch abort"),
             (4, FAULT_PANIC, FAULT_PANIC, "panic", "injected by the host"),
             (5, LOCK_TWICE, FAULT_PANIC, "lock_twice", "'selftest_twice' already held"),
             (6, UNLOCK_FREE, FAULT_PANIC, "unlock_free", "'selftest_free' not held")]
    for core, kind, want_kind, label, want_text in cases:
        before = len(b.faults)
        cmd, st, rest = b.cmd(CMD_FAULT_INJECT, struct.pack("<HB", core, kind))
        got = None
        try:
            b.wait_faults(before + 1)
            got = b.faults[before]
        except (TimeoutError, EOFError) as e:
            got = None
            why = str(e)
        if got:
            fcore, frole, fkind, addr, pc, status, ftext = got
            ok = st == 0 and fcore == core and frole == 2 and fkind == want_kind and want_text in ftext
            if kind in (FAULT_DATA, FAULT_PREFETCH):
                ok = ok and addr & ~1 == UNMAPPED_VIRT
            why = "result %d, fault core %d role %d kind %d addr 0x%x '%s'" % (
                st, fcore, frole, fkind, addr, ftext)
        check("fw_fault_%s_reported" % label, got is not None and ok, why)
    cmd, st, rest = b.cmd(CMD_STATUS)
    halted = struct.unpack("<HHH", rest[:6])[2] if st == 0 else -1
    check("fw_fault_status_counts_halted", st == 0 and halted == len(cases),
          "status %d, %d halted" % (st, halted))
    cmd, st, rest = b.cmd(CMD_LINE_PING, timeout=60)
    check("fw_fault_others_answer", st == ERR_TIMEOUT and "%d of %d serial lines" % (smp - 1 - len(cases), smp - 1) in text(rest),
          "got status %d '%s'" % (st, text(rest)))
    before = len(b.faults)
    cmd, st, rest = b.cmd(CMD_FAULT_INJECT, struct.pack("<HB", 2, FAULT_UNDEF))
    check("fw_fault_halted_core_refused", st == ERR_BAD_ARGS and "already halted" in text(rest),
          "got status %d '%s'" % (st, text(rest)))


def small_ram_check(elf):
    """A board with less RAM than the linker script carved is refused at
    boot with a fault naming both sizes, not left to crash later."""
    b = Board(elf, 3, ram_mb=256)
    try:
        b.wait_faults(1)
        core, role, kind, addr, pc, status, ftext = b.faults[0]
        check("fw_small_ram_refused", core == 0 and kind == FAULT_PANIC and
              "256 MiB" in ftext and "needs 512 MiB" in ftext and not b.hellos,
              "fault core %d kind %d '%s', %d hellos" % (core, kind, ftext, len(b.hellos)))
    except (TimeoutError, EOFError, RuntimeError) as e:
        check("fw_small_ram_refused", False, str(e))
    finally:
        b.stop()


def main():
    elf, smp = sys.argv[1], int(sys.argv[2])
    if not os.path.exists(elf):
        print("FAIL fw_board: firmware %s is not built (run make)" % elf)
        return 1
    small_ram_check(elf)
    b = Board(elf, smp)
    try:
        b.wait_hellos(smp)
        check("fw_all_reported", len(b.hellos) == smp, "%d of %d" % (len(b.hellos), smp))
        bad_input_checks(b, smp)
        fault_checks(b, smp)
    except (TimeoutError, EOFError, RuntimeError) as e:
        print("FAIL fw_board: %s" % e)
        return 1
    finally:
        b.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
