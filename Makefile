# pipetrace -- Makefile.  Keep it small: a table of contents of the program.
# See LICENSE for copyright and license.
#
#   make           build build/pipetrace
#   make run       build and render the built-in scene
#   make test      build and run every test; last line "N passed, N failed"
#   make golden    rewrite traces/ from docs/examples/ (on purpose only)
#   make sanitize  run the tests under -fsanitize=address,undefined
#   make clean

CC      ?= cc
# Warnings (gcc and clang must both be silent):
WARN    = -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
          -Wmissing-prototypes -Wdouble-promotion -Wundef
# IEEE double in the formulas' order: no fused multiply-add, no fast-math.
FPFLAGS = -ffp-contract=off
CFLAGS  ?= -O2 -g
ALLCFLAGS = -std=c11 $(WARN) $(FPFLAGS) $(CFLAGS)
LDLIBS  = -lm
B       = build

# The stages, in pipeline order, then the driver.
STAGES_O = $B/pt_stage.o $B/s1_model2camera.o $B/s2_camera2image.o \
           $B/s3_image2pixel.o $B/s4_pixel2viewport.o $B/s5_viewport2fb.o \
           $B/s6_fb2index.o
SRC_O    = $B/scene.o $B/pipeline.o $B/raster.o $B/fb.o $B/numfmt.o \
           $B/trace.o $B/outfile.o $B/builtin.o
TESTS    = $B/test_stages $B/test_raster $B/test_numfmt $B/test_scene \
           $B/test_reference $B/test_fuzz

all: $B/pipetrace

$B/pipetrace: $B/main.o $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $^ $(LDLIBS)

$B/libpipetrace.a: $(STAGES_O) $(SRC_O)
	rm -f $@ && ar rcs $@ $^

$B/%.o: stages/%.c stages/*.h | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/%.c src/*.h stages/*.h | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/builtin.o: $B/builtin.c src/builtin.h
	$(CC) $(ALLCFLAGS) -Isrc -c -o $@ $<
# The built-in scene is docs/examples/builtin.scene, embedded as a C string.
$B/builtin.c: docs/examples/builtin.scene | $B
	awk 'BEGIN { print "#include \"builtin.h\""; print "const char pt_builtin_scene[] =" } \
	     { gsub(/\\/, "\\\\"); gsub(/"/, "\\\""); print "    \"" $$0 "\\n\"" } \
	     END { print "    \"\";" }' $< > $@
$B/test_%: tests/test_%.c tests/testhelp.h $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -Isrc -Istages -o $@ $< $B/libpipetrace.a $(LDLIBS)
$B:
	mkdir -p $B

run: $B/pipetrace
	$B/pipetrace --image $B/builtin.ppm --trace -
	@echo "image written to $B/builtin.ppm"

test: $B/pipetrace $(TESTS)
	@sh tests/run.sh $B

golden: $B/pipetrace
	sh tests/golden.sh $B/pipetrace --write

sanitize:
	$(MAKE) B=build-san CFLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all" test

clean:
	rm -rf build build-san

.PHONY: all run test golden sanitize clean
