# tests/: host unit tests (built with ASan+UBSan) and board tests.
HOST_TESTS += test_crc32
test_crc32_SRCS := tests/host/test_crc32.c
test_crc32_ARITH := double
