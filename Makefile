# pipetrace -- Makefile.  Keep it small: a table of contents of the program.
# See LICENSE for copyright and license.
#
#   make           build build/pipetrace
#   make run       build and render the built-in scene
#   make test      build and run every test; last line "N passed, N failed"
#   make golden    rewrite traces/ from docs/examples/ (on purpose only)
#   make docs      rewrite the outputs shown in the docs (on purpose only)
#   make screenshots  rewrite docs/journey-* (needs chromium; on purpose only)
#   make sanitize  run the tests under -fsanitize=address,undefined
#   make bench     time parsing, stages, rasterizer and trace output
#   make check-stage STAGE_pixel=FILE.c   a student stage's self-check
#   make clean

CC      ?= cc
# Warnings (gcc and clang must both be silent):
WARN    = -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
          -Wmissing-prototypes -Wdouble-promotion -Wundef
# IEEE double in the formulas' order: no fused multiply-add, no fast-math.
FPFLAGS = -ffp-contract=off
CFLAGS  ?= -O2 -g
# Includes name their layer: "stages/pt_stage.h", "core/pipetrace.h", "io/trace.h".
ALLCFLAGS = -std=c11 $(WARN) $(FPFLAGS) -I. -Isrc $(CFLAGS)
LDLIBS  = -lm
B       = build

# ===== student stages (docs/teaching.md) =====
# `make STAGE_pixel=FILE.c` builds build-student/pipetrace with FILE.c in place
# of stages/s3_image2pixel.c; build/ stays the reference.  One variable a stage:
# STAGE_camera (s1), STAGE_projection (s2), STAGE_pixel (s3), STAGE_viewport (s4),
# STAGE_framebuffer (s5), STAGE_index (s6).  FILE.c includes its stage's header
# by name (-Istages); $B/choice remembers the files, so a new choice rebuilds
# the stage objects (each depends on it), hence the library and the binary.
# The stage rules below must not become the default goal: `make STAGE_x=F`
# with no target builds $B/pipetrace.
.DEFAULT_GOAL := all
CHOICE  = camera=$(STAGE_camera) projection=$(STAGE_projection) pixel=$(STAGE_pixel) \
          viewport=$(STAGE_viewport) framebuffer=$(STAGE_framebuffer) index=$(STAGE_index)
ifneq ($(strip $(STAGE_camera)$(STAGE_projection)$(STAGE_pixel)$(STAGE_viewport)$(STAGE_framebuffer)$(STAGE_index)),)
B       = build-student
$(shell mkdir -p $B; echo '$(CHOICE)' | cmp -s - $B/choice || echo '$(CHOICE)' > $B/choice)
STAGE_CC = $(CC) $(ALLCFLAGS) -Istages -c -o $@ $<
STUDENT  = $(strip $(if $(STAGE_camera),camera) $(if $(STAGE_projection),projection) \
           $(if $(STAGE_pixel),pixel) $(if $(STAGE_viewport),viewport) \
           $(if $(STAGE_framebuffer),framebuffer) $(if $(STAGE_index),index))
CHOSEN   = $B/choice
$B/s1_model2camera.o:   $(or $(STAGE_camera),stages/s1_model2camera.c) stages/*.h $B/choice; $(STAGE_CC)
$B/s2_camera2image.o:   $(or $(STAGE_projection),stages/s2_camera2image.c) stages/*.h $B/choice; $(STAGE_CC)
$B/s3_image2pixel.o:    $(or $(STAGE_pixel),stages/s3_image2pixel.c) stages/*.h $B/choice; $(STAGE_CC)
$B/s4_pixel2viewport.o: $(or $(STAGE_viewport),stages/s4_pixel2viewport.c) stages/*.h $B/choice; $(STAGE_CC)
$B/s5_viewport2fb.o:    $(or $(STAGE_framebuffer),stages/s5_viewport2fb.c) stages/*.h $B/choice; $(STAGE_CC)
$B/s6_fb2index.o:       $(or $(STAGE_index),stages/s6_fb2index.c) stages/*.h $B/choice; $(STAGE_CC)
endif
# ===== end of student stages =====
# $B/buildinfo.c names the stages replaced ("" in build/): pipetrace step and
# --version say so (pt_student_stages, src/tools/cli.h).
$B/buildinfo.c: Makefile $(CHOSEN) | $B
	printf '#include "tools/cli.h"\nconst char pt_student_stages[] = "%s";\n' '$(STUDENT)' > $@

# The layers, bottom up (docs/architecture.md; tests/layers.py checks that
# none includes a header of a layer above it).
# stages/: the formulas, in pipeline order: what all share, the classic
# camera's, then the matrix camera's own (it shares s5 and s6).
STAGES_O = $B/pt_stage.o $B/pt_round.o $B/s1_model2camera.o $B/s2_camera2image.o \
           $B/s3_image2pixel.o $B/s4_pixel2viewport.o $B/s5_viewport2fb.o \
           $B/s6_fb2index.o $B/pt_classic.o \
           $B/pt_mat4.o $B/m1_model2world.o $B/m2_world2view.o $B/m3_view2clip.o \
           $B/m4_clip2cvv.o $B/m5_clip2ndc.o $B/m6_ndc2screen.o \
           $B/m7_screen2viewport.o $B/pt_matrix.o
# src/core/: scene, plan, run, clip, raster, framebuffer (one public header).
CORE_O   = $B/scene.o $B/builtin.o $B/vjourney.o $B/pipeline.o $B/clip.o $B/raster.o $B/fb.o
# src/io/: numbers as text, trace writers and readers, images, output files.
IO_O     = $B/numfmt.o $B/sbuf.o $B/explain.o $B/trace.o $B/tread.o $B/tread_text.o \
           $B/tread_jsonl.o $B/tread_image.o $B/png.o $B/outfile.o
# src/tools/: the command line, the catalogue of formulas and mistakes (diff
# and step), the subcommands (diff, accuracy and journey in folders of their
# own; diff's parts listed with the commands).
TOOLS_O  = $B/cli.o $B/buildinfo.o $B/catalogue.o $B/dd.o $B/acc_shared.o $B/acc_float.o \
           $B/acc_double.o $B/acc_dd.o $B/accuracy.o $B/journey.o $B/journey_html.o
CMDS_O   = $B/cmd_diff.o $B/dprint.o $B/dimage.o $B/dvertex.o $B/dexplain.o $B/dfit.o \
           $B/dpixels.o $B/dsummary.o $B/cmd_step.o $B/cmd_why.o $B/cmd_quiz.o \
           $B/cmd_accuracy.o $B/cmd_journey.o $B/cmd_stages.o
TESTS    = $B/test_stages $B/test_raster $B/test_numfmt $B/test_scene \
           $B/test_reference $B/test_fuzz $B/test_matrix $B/test_explain \
           $B/test_accuracy $B/test_png $B/test_catalogue

all: $B/pipetrace

$B/pipetrace: $B/main.o $(CMDS_O) $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $^ $(LDLIBS)

$B/libpipetrace.a: $(STAGES_O) $(CORE_O) $(IO_O) $(TOOLS_O)
	rm -f $@ && ar rcs $@ $^

HDRS     = stages/*.h src/*/*.h src/tools/*/*.h
$B/%.o: stages/%.c stages/*.h | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/core/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/io/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/tools/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/tools/diff/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/tools/accuracy/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/tools/journey/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/builtin.o: $B/builtin.c src/core/builtin.h
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/buildinfo.o: $B/buildinfo.c src/tools/cli.h
	$(CC) $(ALLCFLAGS) -c -o $@ $<
# The built-in scene is docs/examples/builtin.scene, embedded as a C string.
$B/builtin.c: docs/examples/builtin.scene Makefile | $B
	awk 'BEGIN { print "#include \"core/builtin.h\""; print "const char pt_builtin_scene[] =" } \
	     { gsub(/\\/, "\\\\"); gsub(/"/, "\\\""); print "    \"" $$0 "\\n\"" } \
	     END { print "    \"\";" }' $< > $@
$B/bench: tests/bench.c $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $< $B/libpipetrace.a $(LDLIBS)
$B/test_%: tests/test_%.c tests/testhelp.h tests/refcases.h $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $< $B/libpipetrace.a $(LDLIBS)
$B:
	mkdir -p $B

run: $B/pipetrace
	$B/pipetrace --image $B/builtin.ppm --trace -
	@echo "image written to $B/builtin.ppm"

test: $B/pipetrace $(TESTS)
	@sh tests/run.sh $B

golden: $B/pipetrace
	sh tests/golden.sh $B/pipetrace --write

docs: $B/pipetrace
	python3 tests/docs_write.py $B/pipetrace README.md docs/*.md docs/exercises/*.md

screenshots: $B/pipetrace
	$B/pipetrace journey --vertex 1 --svg docs/journey-builtin.svg
	sh tests/journey_browser.sh $B/pipetrace $B/journey-shots
	cp $B/journey-shots/journey-builtin.png docs/journey-builtin.png
	cp $B/journey-shots/journey-page-stage4.png docs/journey-page.png

bench: $B/bench
	$B/bench

# The self-check of a student stage (docs/teaching.md): `make check-stage
# STAGE_pixel=FILE.c` builds the student build and the reference (build/),
# runs both on docs/examples/selfcheck.scene, and the reference's diff says
# whether the stage passes, and if not where and why.
SELFCHECK = docs/examples/selfcheck.scene
check-stage: $B/pipetrace
	@test -n "$(STUDENT)" || { echo "make check-stage: name the stage file, e.g. make check-stage STAGE_pixel=FILE.c" >&2; exit 2; }
	@$(MAKE) -s B=build STAGE_camera= STAGE_projection= STAGE_pixel= STAGE_viewport= \
	    STAGE_framebuffer= STAGE_index= build/pipetrace
	@build/pipetrace $(SELFCHECK) --format jsonl --trace $B/selfcheck-reference.jsonl
	@$B/pipetrace $(SELFCHECK) --format jsonl --trace $B/selfcheck-yours.jsonl
	@echo "check-stage: your $(STUDENT) stage on $(SELFCHECK), against the reference"
	@build/pipetrace diff --show 3 --verdict $B/selfcheck-reference.jsonl $B/selfcheck-yours.jsonl

sanitize:
	$(MAKE) B=build-san CFLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all" test

clean:
	rm -rf build build-san build-student

.PHONY: all run test golden docs screenshots bench sanitize clean check-stage
