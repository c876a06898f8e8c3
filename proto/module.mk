# proto/: what the firmware and the host tools share: wire and file formats,
# result layouts, the arithmetic codes, the core counts, the area schedules.
SHARED_SRCS += proto/crc32.c proto/hostlink.c proto/arith.c proto/areas.c
