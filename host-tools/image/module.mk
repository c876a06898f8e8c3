# host-tools/image/: image files (PNG through libpng, PPM) and comparing
# two images (PSNR, pixels beyond a tolerance, lost pixels matched).
HT_IMAGE_IO_SRCS := host-tools/image/image_io.c
HT_IMAGE_COMPARE_SRCS := host-tools/image/image_compare.c
# Films: frames piped to the ffmpeg command (links1 render -o FILM.mp4).
# Films and image files written whole (both through opts/out_file).
# Charts: a gnuplot script piped to the gnuplot command (links1 replay --timeline).
HT_IMAGE_FILM_SRCS := host-tools/image/film.c host-tools/image/image_save.c host-tools/image/chart.c
ARITH_FREE_SRCS += $(HT_IMAGE_IO_SRCS) $(HT_IMAGE_FILM_SRCS)
# (image_compare.c reads render/render.h for the --mark-lost colour)

test_scene_image_SRCS = tests/host/test_scene_image.c $(HT_IMAGE_IO_SRCS) host-tools/image/image_save.c \
	$(HT_IMAGE_COMPARE_SRCS) host-tools/cli/cmd_compare.c $(HT_OPTS_CLI_SRCS)
test_scene_image_ARITH := double
test_scene_image_LIBS := -lpng -lm
