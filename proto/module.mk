# proto/: what the firmware and the host tools share: wire and file formats,
# result layouts, the arithmetic codes, the core counts, the area schedules,
# the text formatter.
SHARED_SRCS += proto/crc32.c proto/wordsum.c proto/hostlink.c proto/link_arq.c proto/arith.c proto/areas.c proto/textfmt.c proto/machines.c
# None of them knows num_t: one build serves every arithmetic's host programs.
ARITH_FREE_SRCS += proto/crc32.c proto/wordsum.c proto/hostlink.c proto/link_arq.c proto/arith.c proto/areas.c proto/textfmt.c proto/machines.c

# The shared formatter against the host's snprintf.
test_textfmt_SRCS := tests/host/test_textfmt.c
test_textfmt_ARITH := double
