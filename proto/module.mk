# proto/: wire and file formats shared by the firmware and the host tools.
SHARED_SRCS += proto/crc32.c proto/hostlink.c
