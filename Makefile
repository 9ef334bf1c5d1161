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
#   make fuzz      build the libFuzzer targets (clang) and run each FUZZ_SECONDS
#   make mutate    apply each listed mutation alone; its tests must fail
#   make install   copy the program, its man page and docs under PREFIX
#                  (default /usr/local; DESTDIR is put in front, for packages)
#   make uninstall remove what make install copied
#   make check-stage STAGE_pixel=FILE.c   a student stage's self-check
#   make clean

CC      ?= cc
# Warnings (gcc and clang must both be silent):
WARN    = -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wswitch-enum \
          -Wmissing-prototypes -Wdouble-promotion -Wundef
# IEEE double in the formulas' order: no fused multiply-add, no fast-math.
FPFLAGS = -ffp-contract=off
CFLAGS  ?= -O2 -g
# Debug information as DWARF 4 with any compiler: valgrind 3.19 cannot read the
# DWARF 5 clang 14 writes (tests/cli/valgrind.sh).  CFLAGS=-g0 turns it off.
DEBUGFMT = -gdwarf-4
# Includes name their layer: "stages/pt_stage.h", "core/pipetrace.h", "io/trace.h".
ALLCFLAGS = -std=c11 $(WARN) $(FPFLAGS) -I. -Isrc $(DEBUGFMT) $(CFLAGS)
LDLIBS  = -lm -pthread
B       = build

# ===== student stages (docs/teaching.md) =====
# `make STAGE_pixel=FILE.c` builds build-student/pipetrace with FILE.c in place
# of stages/s3_image2pixel.c; build/ stays the reference.  One variable a stage,
# named as the trace names it: STAGE_camera (s1), STAGE_image (s2; also
# STAGE_projection), STAGE_pixel (s3), STAGE_viewport (s4), STAGE_framebuffer
# (s5), STAGE_index (s6).  The names are not typed here: src/tools/stage_names.c
# prints them from the stage table (the k-th is stages/sK_*.c's), and an
# unknown STAGE_x stops make with the list.  FILE.c includes its stage's header
# by name (-Istages); $B/choice remembers the files and $B/choice-NAME each
# stage's, so a new choice rebuilds that stage's object (and what includes
# the chosen files), hence the library and the binary.
# The old $B/pipetrace is removed first, so a failed build leaves none that
# does not match the files given.  The stage rules below must not become the
# default goal: `make STAGE_x=F` with no target builds $B/pipetrace.
.DEFAULT_GOAL := all
STAGE_GIVEN := $(sort $(foreach v,$(filter STAGE_%,$(.VARIABLES)),$(if $(strip $($v)),$v)))
ifneq ($(STAGE_GIVEN),)
B       = build-student
STAGE_NAMES := $(shell mkdir -p $B && rm -f $B/pipetrace && $(CC) -std=c11 -I. -Isrc \
               -o $B/stage-names src/tools/stage_names.c stages/pt_stage.c -lm && $B/stage-names)
STAGE_FILES := $(sort $(wildcard stages/s[1-9]_*.c))
ifneq ($(words $(STAGE_NAMES)),$(words $(STAGE_FILES)))
$(error cannot match the stage names ($(STAGE_NAMES)) with stages/s*_*.c; is $(CC) working?)
endif
STAGE_BAD := $(filter-out $(addprefix STAGE_,$(STAGE_NAMES) projection),$(STAGE_GIVEN))
ifneq ($(STAGE_BAD),)
$(error unknown student stage $(STAGE_BAD); the stages are $(addprefix STAGE_,$(STAGE_NAMES)) (STAGE_projection is STAGE_image))
endif
ifneq ($(and $(STAGE_projection),$(STAGE_$(word 2,$(STAGE_NAMES)))),)
$(error STAGE_projection is STAGE_$(word 2,$(STAGE_NAMES)): give one of them)
endif
STAGE_$(word 2,$(STAGE_NAMES)) := $(or $(STAGE_$(word 2,$(STAGE_NAMES))),$(STAGE_projection))
$(foreach n,$(STAGE_NAMES),$(if $(STAGE_$n),$(if $(wildcard $(STAGE_$n)),,\
    $(error STAGE_$n=$(STAGE_$n): no such file))))
CHOICE  = $(foreach n,$(STAGE_NAMES),$n=$(STAGE_$n))
$(shell echo '$(CHOICE)' | cmp -s - $B/choice || echo '$(CHOICE)' > $B/choice)
# and $B/choice-NAME each stage's own, so that a build reusing another's
# objects (tests/lib/studentlib.sh) compiles again only the stages whose file
# changed, not all of them
$(foreach n,$(STAGE_NAMES),$(shell echo '$(STAGE_$n)' | cmp -s - $B/choice-$n || \
    echo '$(STAGE_$n)' > $B/choice-$n))
STAGE_CC = $(CC) $(ALLCFLAGS) -Istages -c -o $@ $<
STUDENT  = $(strip $(foreach n,$(STAGE_NAMES),$(if $(STAGE_$n),$n)))
STUDENT_FILES = $(foreach n,$(STUDENT),$(STAGE_$n))
CHOSEN   = $B/choice $(STUDENT_FILES)
# stage_rule NAME FILE: $B/sK_*.o from the student's file for NAME, or from FILE
define stage_rule
$$B/$(notdir $(2:.c=.o)): $$(or $$(STAGE_$1),$2) stages/*.h $$B/choice-$1; $$(STAGE_CC)
endef
$(foreach p,$(join $(addsuffix :,$(STAGE_NAMES)),$(STAGE_FILES)),\
    $(eval $(call stage_rule,$(word 1,$(subst :, ,$p)),$(word 2,$(subst :, ,$p)))))
# (viewport, framebuffer and index are compiled into $B/pixelpath.o, below)
endif
# ===== end of student stages =====
# $B/buildinfo.c names the stages replaced ("" in build/): pipetrace step and
# --version say so (pt_student_stages, src/tools/cli.h); every trace header
# names the files (without their folders), each with its cksum as 8 hex
# digits (pt_student_files).
$B/buildinfo.c: Makefile $(CHOSEN) | $B
	printf '#include "tools/cli.h"\nconst char pt_student_stages[] = "%s";\n' '$(STUDENT)' > $@
	printf 'const char pt_student_files[] = "%s";\n' "$(strip $(foreach n,$(STUDENT),\
	    $n=$(notdir $(STAGE_$n))#$$(cksum < '$(STAGE_$n)' | awk '{ printf "%08x", $$1 }')))" >> $@

# The layers, bottom up (docs/architecture.md; tests/repo/layers.py checks that
# none includes a header of a layer above it).
# stages/: the formulas, in pipeline order: what all share, the classic
# camera's, then the matrix camera's own (it shares s5 and s6).
STAGES_O = $B/pt_stage.o $B/pt_round.o $B/pt_jmath.o $B/pt_color.o $B/s1_model2camera.o $B/s2_camera2image.o \
           $B/s3_image2pixel.o $B/pt_classic.o \
           $B/pt_mat4.o $B/m1_model2world.o $B/m2_world2view.o $B/m3_view2clip.o \
           $B/m4_clip2cvv.o $B/m5_clip2ndc.o $B/m6_ndc2screen.o \
           $B/m7_screen2viewport.o $B/ms_clip_segment.o $B/pt_matrix.o $(RV_O) $(REF_O)
# The course's renderers 7 and 9 (stages/rv_model.h): their stages.
RV_O     = $B/rv_model.o $B/r7_model2view.o $B/r7_view2camera.o $B/r9_matrix.o \
           $B/r9_model2world.o $B/r9_world2view.o $B/r9_view2camera.o $B/rv_nearclip.o \
           $B/rv_project.o $B/rv_clip.o $B/rv_raster.o
# The reference copy of s1..s6, in every build (stages/pt_ref.h): each file
# compiled again with stages/pt_ref_names.h in front, which renames its
# function pt_x to ptref_x; in build-student/ these stay the reference while
# the pt_ ones are the student's.  The tools call them for "the formula".
REF_O    = $B/ref_s1_model2camera.o $B/ref_s2_camera2image.o $B/ref_s3_image2pixel.o \
           $B/ref_s4_pixel2viewport.o $B/ref_s5_viewport2fb.o $B/ref_s6_fb2index.o $B/pt_ref.o
# src/core/: scene, plan, run (the pipelines), raster, framebuffer (one public header).
# pixelpath.o is the rasterizer with the stages s4, s5 and s6 (see below).
CORE_O   = $B/scene.o $B/scene_course.o $B/nameset.o $B/numparse.o $B/shapes.o $B/builtin.o $B/vjourney.o \
           $B/pipeline.o $B/pixelpath.o $B/raster_advance.o $B/raster_point.o $B/fb.o \
           $B/course.o
# src/io/: numbers as text, trace writers and readers, images, output files.
IO_O     = $B/numfmt.o $B/jnum.o $B/sbuf.o $B/explain.o $B/explain_course.o $B/trace_buf.o $B/trace_head.o \
           $B/trace_text.o $B/trace_jsonl.o $B/trace_csv.o $B/trace.o $B/tread.o \
           $B/tread_util.o $B/tread_text.o $B/tread_jsonl.o $B/tread_kraft.o $B/tread_image.o \
           $B/png.o $B/outfile.o $B/trace_kraft.o $B/trace_kraft_check.o $B/tlanes.o \
           $B/trace_course.o $B/trace_course_rec.o $B/rv_log_raster.o $B/tread79.o
# src/tools/: the command line, the catalogue of formulas and mistakes (diff
# and step), the subcommands (diff, accuracy and journey in folders of their
# own; diff's parts listed with the commands).
TOOLS_O  = $B/cli.o $B/buildinfo.o $B/catalogue.o $B/catalogue79.o $B/dd.o $B/acc_shared.o $B/acc_float.o \
           $B/acc_double.o $B/acc_dd.o $B/accuracy.o $B/jdraw.o $B/jplace.o $B/jpanel.o \
           $B/journey_classic.o $B/journey_matrix.o $B/jrows.o $B/journey.o $B/journey_html.o \
           $B/journey_course.o $B/journey_wasm.o $B/stages_wasm.o
CMDS_O   = $B/cmd_diff.o $B/dprint.o $B/dimage.o $B/dvertex.o $B/dexplain.o $B/dfit.o \
           $B/dpixels.o $B/dsummary.o $B/dsearch.o $B/dseparate.o $B/dseparate79.o $B/d79.o $B/cmd_step.o $B/cmd_why.o $B/why_course.o \
           $B/cmd_quiz.o $B/quiz79.o \
           $B/cmd_accuracy.o $B/cmd_journey.o $B/cmd_stages.o $B/cmd_shapes.o $B/cmd_export.o \
           $B/export_java.o $B/cmd_class.o $B/class_report.o
TESTS    = $B/test_stages $B/test_raster $B/test_numfmt $B/test_scene \
           $B/test_reference $B/test_fuzz $B/test_matrix $B/test_explain \
           $B/test_accuracy $B/test_png $B/test_catalogue $B/test_jnum $B/test_jmath \
           $B/test_tread $B/test_nameset $B/test_numparse $B/test_shapes $B/test_wasm_libm \
           $B/test_numfmt_portable $B/test_trace $B/test_lanes $B/test_pipelines \
           $B/test_journey $B/test_rv_stages $B/test_rv_raster $B/test_lanes79

all: $B/pipetrace

$B/pipetrace: $B/main.o $(CMDS_O) $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $^ $(LDLIBS)

$B/libpipetrace.a: $(STAGES_O) $(CORE_O) $(IO_O) $(TOOLS_O)
	rm -f $@ && ar rcs $@ $^

HDRS     = stages/*.h src/*/*.h src/tools/*/*.h
$B/%.o: stages/%.c stages/*.h | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/ref_%.o: stages/%.c stages/*.h | $B
	$(CC) $(ALLCFLAGS) -Istages -include stages/pt_ref_names.h -c -o $@ $<
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
$B/%.o: src/tools/class/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/%.o: src/tools/journey/%.c $(HDRS) | $B
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/builtin.o: $B/builtin.c src/core/builtin.h
	$(CC) $(ALLCFLAGS) -c -o $@ $<
$B/buildinfo.o: $B/buildinfo.c src/tools/cli.h
	$(CC) $(ALLCFLAGS) -c -o $@ $<
# The rasterizer (src/core/raster.c) and the stages it calls for every pixel,
# viewport, framebuffer and index (a student's files when chosen), compiled as
# one translation unit, so that the compiler can inline them into the DDA's
# loop (docs/bench.md); the stages stay the files they are.
PIXEL_SRC = $(or $(STAGE_viewport),stages/s4_pixel2viewport.c) \
            $(or $(STAGE_framebuffer),stages/s5_viewport2fb.c) \
            $(or $(STAGE_index),stages/s6_fb2index.c) src/core/raster.c
# (in a student build, remade when the viewport, framebuffer or index file
# chosen changes, not when another stage's does)
PIXEL_CHOSEN = $(if $(STAGE_GIVEN),$(addprefix $B/choice-,viewport framebuffer index))
$B/pixelpath.c: Makefile $(PIXEL_CHOSEN) | $B
	printf '#include "%s"\n' $(abspath $(PIXEL_SRC)) > $@
$B/pixelpath.o: $B/pixelpath.c $(PIXEL_SRC) $(HDRS)
	$(CC) $(ALLCFLAGS) -Istages -c -o $@ $<
# The built-in scene is docs/examples/builtin.scene, embedded as a C string.
$B/builtin.c: docs/examples/builtin.scene Makefile | $B
	awk 'BEGIN { print "#include \"core/builtin.h\""; print "const char pt_builtin_scene[] =" } \
	     { gsub(/\\/, "\\\\"); gsub(/"/, "\\\""); print "    \"" $$0 "\\n\"" } \
	     END { print "    \"\";" }' $< > $@
# ===== the journey page's stages in WebAssembly (docs/journey.md) =====
# Both cameras' stage files (a student's when chosen), compiled by
# clang for wasm32 without libc (src/wasm/: the glue and the few libm
# functions) and linked by wasm-ld into $B/stages.wasm, which the page
# embeds as base64 ($B/stages_wasm.c).  WASM=yes when both tools are found
# (Debian: clang, lld); `make WASM=no` builds the page without its sliders,
# as a build without them does.  A student build (STAGE_x=FILE.c) has none
# unless WASM=yes: the file may call what the build without libc lacks.
# rv_raster.c is there for pt_rv_fb_index() alone: wasm-ld keeps only what
# the glue calls, so its drawing (pt_color.c's pow) is left out.
# $B/wasm-choice remembers the choice.
WASM_CC  = clang
WASM_LD  = wasm-ld
WASM    := $(if $(STAGE_GIVEN),no,$(if $(and $(shell command -v $(WASM_CC) 2>/dev/null),$(shell command -v $(WASM_LD) 2>/dev/null)),yes,no))
# -mbulk-memory: a struct copy becomes memory.copy, not a call to libc's memcpy.
WASM_CFLAGS = --target=wasm32 -ffreestanding -nostdlib -std=c11 $(WARN) $(FPFLAGS) -O2 \
              -mbulk-memory -isystem src/wasm -I. -Isrc -Istages
WASM_SRC = src/wasm/pt_wasm.c src/wasm/pt_wasm_libm.c stages/pt_stage.c stages/pt_round.c \
           $(or $(STAGE_camera),stages/s1_model2camera.c) \
           $(or $(STAGE_image),stages/s2_camera2image.c) \
           $(or $(STAGE_pixel),stages/s3_image2pixel.c) \
           $(or $(STAGE_viewport),stages/s4_pixel2viewport.c) \
           $(or $(STAGE_framebuffer),stages/s5_viewport2fb.c) \
           $(or $(STAGE_index),stages/s6_fb2index.c) stages/pt_classic.c \
           stages/pt_mat4.c stages/pt_matrix.c stages/m1_model2world.c \
           stages/m2_world2view.c stages/m3_view2clip.c stages/m4_clip2cvv.c stages/m5_clip2ndc.c \
           stages/m6_ndc2screen.c stages/m7_screen2viewport.c \
           src/wasm/pt_wasm_alloc.c stages/rv_model.c stages/r7_model2view.c \
           stages/r7_view2camera.c stages/r9_matrix.c stages/r9_model2world.c \
           stages/r9_world2view.c stages/r9_view2camera.c stages/rv_nearclip.c \
           stages/rv_project.c stages/rv_clip.c stages/rv_raster.c
$(shell mkdir -p $B && { echo '$(WASM)' | cmp -s - $B/wasm-choice || echo '$(WASM)' > $B/wasm-choice; })
$B/stages.wasm: $(WASM_SRC) stages/*.h stages/wasm/*.h src/wasm/*.h $B/wasm-choice $(CHOSEN)
	rm -rf $B/wasm-obj && mkdir -p $B/wasm-obj
	n=0; for f in $(WASM_SRC); do n=$$((n + 1)); \
	    $(WASM_CC) $(WASM_CFLAGS) -c -o $B/wasm-obj/$$n.o $$f || exit 1; done
	$(WASM_LD) --no-entry --strip-all -o $@ $B/wasm-obj/*.o
$B/stages_wasm.c: $B/wasm-choice $(if $(filter yes,$(WASM)),$B/stages.wasm)
	{ echo '#include "tools/journey/journey_wasm.h"'; \
	  echo 'const char *const pt_journey_wasm_b64[] = {'; \
	  if [ '$(WASM)' = yes ]; then base64 $B/stages.wasm | awk '{ print "    \"" $$0 "\"," }'; fi; \
	  echo '    NULL'; echo '};'; } > $@
$B/stages_wasm.o: $B/stages_wasm.c src/tools/journey/journey_wasm.h
	$(CC) $(ALLCFLAGS) -c -o $@ $<
# tests/unit/test_wasm_libm.c includes the module's fmax and ilogb to compare them with libm.
$B/test_wasm_libm: src/wasm/pt_wasm_libm.c src/wasm/pt_wasm_libm.h
# tests/test_fuzz also replays the fuzz targets' regression corpus (tests/fuzz/).
FUZZ_C   = tests/fuzz/fuzz_scene.c tests/fuzz/fuzz_obj.c tests/fuzz/fuzz_trace.c \
           tests/fuzz/fuzz_image.c tests/fuzz/fuzz_common.c
$B/test_fuzz: tests/unit/test_fuzz.c $(FUZZ_C) tests/fuzz/fuzz.h tests/unit/testhelp.h $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ tests/unit/test_fuzz.c $(FUZZ_C) $B/libpipetrace.a $(LDLIBS)
$B/test_tread: tests/unit/test_tread.c tests/fuzz/fuzz_common.c tests/fuzz/fuzz.h tests/unit/testhelp.h \
               $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ tests/unit/test_tread.c tests/fuzz/fuzz_common.c $B/libpipetrace.a $(LDLIBS)
# make bench: the benchmark (tests/bench/bench.c), its scene generator and the
# plain-C baseline it compares with (docs/bench.md).
$B/bench: tests/bench/bench.c $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $< $B/libpipetrace.a $(LDLIBS)
$B/benchgen: tests/bench/benchgen.c | $B
	$(CC) $(ALLCFLAGS) -o $@ $<
$B/baseline: tests/bench/baseline.c | $B
	$(CC) $(ALLCFLAGS) -o $@ $< $(LDLIBS)
# test_numfmt once more on numfmt.c's portable 64x64-bit product (no __int128).
$B/test_numfmt_portable: tests/unit/test_numfmt.c src/io/numfmt.c src/io/numfmt.h tests/unit/testhelp.h | $B
	$(CC) $(ALLCFLAGS) -DPT_NUMFMT_PORTABLE -o $@ tests/unit/test_numfmt.c src/io/numfmt.c $(LDLIBS)
$B/test_%: tests/unit/test_%.c tests/unit/testhelp.h tests/unit/refcases.h $B/libpipetrace.a
	$(CC) $(ALLCFLAGS) -o $@ $< $B/libpipetrace.a $(LDLIBS)
$B:
	mkdir -p $B

run: $B/pipetrace
	$B/pipetrace --image $B/builtin.ppm --trace -
	@echo "image written to $B/builtin.ppm"

# make test builds on two jobs unless given -j (CI has two cores), then runs
# the groups in two lanes (tests/run.sh; tests/README.md maps tests/).
TEST_J  = $(if $(findstring -j,$(MAKEFLAGS)),,-j2)
test:
	@$(MAKE) --no-print-directory $(TEST_J) $B/pipetrace $(TESTS) $B/benchgen $B/baseline
	@sh tests/run.sh $B

golden: $B/pipetrace
	sh tests/formats/golden.sh $B/pipetrace --write

docs: $B/pipetrace
	COLUMNS= python3 tests/repo/docs_write.py $B/pipetrace README.md docs/*.md docs/exercises/*.md

screenshots: $B/pipetrace
	$B/pipetrace journey --vertex 1 --svg docs/journey-builtin.svg
	sh tests/journey/journey_browser.sh $B/pipetrace $B/journey-shots
	cp $B/journey-shots/journey-builtin.png docs/journey-builtin.png
	cp $B/journey-shots/journey-page-stage4.png docs/journey-page.png
	cp $B/journey-shots/journey-present.png docs/journey-present.png
	cp $B/journey-shots/journey-matrix.png docs/journey-matrix.png
	$B/pipetrace accuracy --svg docs/accuracy.svg > /dev/null
	$B/pipetrace accuracy docs/examples/lookat-cube.scene --svg docs/accuracy-lookat.svg > /dev/null

bench: $B/bench $B/benchgen $B/baseline $B/pipetrace $B/test_numparse
	$B/test_numparse 2000000
	$B/bench $B
	sh tests/bench/class_bench.sh $B

# The self-check of a student stage (docs/teaching.md): `make check-stage
# STAGE_pixel=FILE.c` builds the student build and the reference (build/),
# runs both on docs/examples/selfcheck.scene, and the reference's diff says
# whether the stage passes, and if not where and why.
SELFCHECK = docs/examples/selfcheck.scene
check-stage: $B/pipetrace
	@test -n "$(STUDENT)" || { echo "make check-stage: name the stage file, e.g. make check-stage STAGE_pixel=FILE.c" >&2; exit 2; }
	@$(MAKE) -s B=build STAGE_camera= STAGE_projection= STAGE_image= STAGE_pixel= STAGE_viewport= \
	    STAGE_framebuffer= STAGE_index= build/pipetrace
	@build/pipetrace $(SELFCHECK) --format jsonl --trace $B/selfcheck-reference.jsonl
	@$B/pipetrace $(SELFCHECK) --format jsonl --trace $B/selfcheck-yours.jsonl
	@echo "check-stage: your $(STUDENT) stage on $(SELFCHECK), against the reference"
	@build/pipetrace diff --show 3 --verdict $B/selfcheck-reference.jsonl $B/selfcheck-yours.jsonl

sanitize:
	$(MAKE) B=build-san CFLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all" test

# ===== fuzzing (tests/fuzz/run.sh) =====
# Each target is linked with libFuzzer; the library is built in build-fuzz/
# with coverage for it.  FUZZ_SECONDS a target, one after another.
FUZZ_CC      = clang
FUZZ_SAN     = -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_SECONDS = 60
FUZZERS      = scene obj trace image
fuzz: fuzz-build $B/pipetrace
	sh tests/fuzz/run.sh $B/pipetrace build-fuzz $(FUZZ_SECONDS) $(FUZZERS)
fuzz-build:
	$(MAKE) B=build-fuzz CC=$(FUZZ_CC) CFLAGS="$(FUZZ_SAN) -fsanitize=fuzzer-no-link" \
	    build-fuzz/libpipetrace.a
	for t in $(FUZZERS); do \
	    $(FUZZ_CC) -std=c11 $(WARN) $(FPFLAGS) -I. -Isrc $(DEBUGFMT) $(FUZZ_SAN) -fsanitize=fuzzer \
	        -DPT_LIBFUZZER -o build-fuzz/fuzz_$$t tests/fuzz/fuzz_$$t.c \
	        tests/fuzz/fuzz_common.c build-fuzz/libpipetrace.a $(LDLIBS) || exit 1; \
	done

# ===== mutation tests (tests/mutate/) =====
# Each mutation of tests/mutate/mutations alone, in a scratch copy: its test
# groups must fail.  Minutes, so not part of `make test`.  MUTANTS=ID... for some.
mutate: $B/pipetrace $(TESTS)
	sh tests/mutate/mutate.sh "$(TESTS:$B/%=build/%) build/pipetrace" $(MUTANTS)

# ===== install =====
# bin/pipetrace, share/man/man1/pipetrace.1, and share/doc/pipetrace/ holding
# README.md, LICENSE and docs/ (so that README's links work there too).
PREFIX  ?= /usr/local
BINDIR  = $(DESTDIR)$(PREFIX)/bin
MAN1DIR = $(DESTDIR)$(PREFIX)/share/man/man1
DOCDIR  = $(DESTDIR)$(PREFIX)/share/doc/pipetrace

install: $B/pipetrace
	mkdir -p $(BINDIR) $(MAN1DIR) $(DOCDIR)
	cp $B/pipetrace $(BINDIR)/pipetrace && chmod 755 $(BINDIR)/pipetrace
	cp docs/pipetrace.1 $(MAN1DIR)/pipetrace.1 && chmod 644 $(MAN1DIR)/pipetrace.1
	cp README.md LICENSE $(DOCDIR)/
	rm -rf $(DOCDIR)/docs && cp -R docs $(DOCDIR)/docs

uninstall:
	rm -f $(BINDIR)/pipetrace $(MAN1DIR)/pipetrace.1
	rm -rf $(DOCDIR)

clean:
	rm -rf build build-san build-student build-fuzz

.PHONY: all run test golden docs screenshots bench sanitize fuzz fuzz-build mutate clean install uninstall \
        check-stage
