# proto/: wire and file formats, and the text formatter, shared by the
# firmware and the host tools.
SHARED_SRCS += proto/crc32.c proto/hostlink.c proto/textfmt.c

# The shared formatter against the host's snprintf.
HOST_TESTS += test_textfmt
test_textfmt_SRCS := tests/host/test_textfmt.c
test_textfmt_ARITH := double
