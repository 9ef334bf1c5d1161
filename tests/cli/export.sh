#!/bin/sh
# tests/cli/export.sh -- pipetrace export java
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/export.sh PIPETRACE
#   export-1  arguments, class names, errors, files written whole or not at all
#   export-2  (with a JDK) the program compiles against a stub of renderer 4's
#             API that this script writes, and hands the stub exactly the
#             scene's doubles, names, indices, colors and sizes
#   export-3  (with the course's jar: PIPETRACE_RENDERER4_JAR=renderer_4.jar, and
#             the course's logs in tests/reference/kraftlog or, failing that,
#             ../shared/reference/kraftlog) every reference
#             scene's program prints, on standard error, the course's log, and
#             writes pipetrace's image
# Parts that need what is not installed say "skipped" and why.
exe=$1
. tests/lib/testlib.sh

# ----------------------------------------------------------------- export-1
cat > "$tmp/odd.scene" <<'SCENE'
framebuffer 10 20
background 4 5 6
viewport 1 2 3 4
model ẞ-𝄞
translate 0.1 -0 1e300
color 1 2 3
v 0.1 -0 1e300
v 5e-324 0.333333333333333314829616256247 2.5e-308
v -123456.789 0 1
l 1 2 3
model empty
SCENE
run export java "$tmp/odd.scene"
check "export-1.1 export java SCENE writes the program to standard output" [ "$rc" -eq 0 ]
check "export-1.2 ... class PipetraceScene" grep -q '^public class PipetraceScene$' "$tmp/out"
check "export-1.3 ... the doubles as Java double literals (-0.0, not -0)" \
    grep -qF 'new Vertex(0.1, -0.0, 1e+300)' "$tmp/out"
check "export-1.4 ... names as ASCII with \\u escapes" grep -qF 'new Model("\u1e9e-\ud834\udd1e")' "$tmp/out"
check "export-1.5 ... the pixel log off without --pixels" grep -qF 'Rasterize.debug = false;' "$tmp/out"
run export java "$tmp/odd.scene" --pixels -o "$tmp/My_Scene2.java"
check "export-1.6 -o FILE.java succeeds" [ "$rc" -eq 0 ]
check "export-1.6 ... and writes FILE.java" [ -s "$tmp/My_Scene2.java" ]
check "export-1.7 ... class FILE" grep -q '^public class My_Scene2$' "$tmp/My_Scene2.java"
check "export-1.8 ... --pixels turns the pixel log on" grep -qF 'Rasterize.debug = true;' "$tmp/My_Scene2.java"
check "export-1.9 ... nothing on standard output" [ ! -s "$tmp/out" ]
run export java "$tmp/odd.scene" -o "$tmp/1bad.java"
check "export-1.10 a FILE that is no Java class name is a usage error" [ "$rc" -eq 1 ]
check "export-1.11 ... and nothing is written" [ ! -e "$tmp/1bad.java" ]
run export java "$tmp/odd.scene" -o "$tmp/Scene.java"
check "export-1.11 a class the program uses (Scene) is refused" [ "$rc" -eq 1 ]
run export java "$tmp/odd.scene" -o "$tmp/class.java"
check "export-1.11 so is a reserved word" [ "$rc" -eq 1 ]
run export java "$tmp/odd.scene" -o "$tmp/Scene.txt"
check "export-1.12 -o needs .java" [ "$rc" -eq 1 ]
check "export-1.12 ... and says so" grep -q 'FILE.java' "$tmp/err"
run export python "$tmp/odd.scene"
check "export-1.13 only java" [ "$rc" -eq 1 ]
run export java docs/examples/lookat-cube.scene -o "$tmp/Look.java"
check "export-1.14 the matrix camera is an input error (renderer 4 has none)" [ "$rc" -eq 2 ]
check "export-1.15 ... that says so" grep -q 'matrix camera' "$tmp/err"
check "export-1.15 ... and writes nothing" [ ! -e "$tmp/Look.java" ]
printf 'model m\nv 1 2\n' > "$tmp/bad.scene"
run export java "$tmp/bad.scene" -o "$tmp/Bad.java"
check "export-1.16 a bad scene: exit 2" [ "$rc" -eq 2 ]
check "export-1.16 ... with FILE:LINE:COL" grep -q "bad.scene:2:1: error" "$tmp/err"
run export java
check "export-1.17 no SCENE: the built-in scene" grep -q 'new Model("cube")' "$tmp/out"
run export --help
check "export-1.18 --help" grep -q '^usage: pipetrace export java' "$tmp/out"
printf 'model big\n' > "$tmp/big.scene"
i=0; while [ $i -lt 1000 ]; do echo "v $i 0.5 -3"; i=$((i + 1)); done >> "$tmp/big.scene"
echo "l $(seq -s ' ' 1 1000)" >> "$tmp/big.scene"
run export java "$tmp/big.scene" -o "$tmp/Big.java"
check "export-1.19 1000 vertices go into classes of at most 400 calls" \
    [ "$(grep -c 'private static final class M1Vertices' "$tmp/Big.java")" -eq 3 ]
# issue 31: outputs over inputs, names javac refuses
cp "$tmp/odd.scene" "$tmp/S.java"
run export java "$tmp/S.java" -o "$tmp/S.java"
check "export-1.20 -o naming the scene: refused, exit 2" [ "$rc" -eq 2 ]
check "export-1.21 ... the scene kept" cmp -s "$tmp/S.java" "$tmp/odd.scene"
ln -s S.java "$tmp/L.java"
run export java "$tmp/L.java" -o "$tmp/S.java"
check "export-1.22 ... through a symbolic link too" [ "$rc" -eq 2 ]
printf 'v 0 0 -2\nv 1 1 -2\nl 1 2\n' > "$tmp/Part.java"
printf 'model m\nobj Part.java\n' > "$tmp/inc.scene"
cp "$tmp/Part.java" "$tmp/part.keep"
run export java "$tmp/inc.scene" -o "$tmp/Part.java"
check "export-1.23 -o naming an OBJ file the scene reads: refused, exit 2" [ "$rc" -eq 2 ]
check "export-1.24 ... saying so, the OBJ kept" \
    sh -c "grep -q 'an OBJ file the scene reads' '$tmp/err' && cmp -s '$tmp/Part.java' '$tmp/part.keep'"
for c in M1Vertices0 M1 M12Segments3; do
    run export java "$tmp/odd.scene" -o "$tmp/$c.java"
    check "export-1.25 -o $c.java, a class the program makes: a usage error" [ "$rc" -eq 1 ]
done
run export java "$tmp/odd.scene" -o "$tmp/M1Vertex.java"
check "export-1.26 ... M1Vertex.java is not one" [ "$rc" -eq 0 ]
i=0; while [ $i -lt 800 ]; do echo "model m$i"; echo "v $i 0 -2"; echo "v $i 1 -2"; echo "l 1 2"
    i=$((i + 1)); done > "$tmp/many.scene"
run export java "$tmp/many.scene" -o "$tmp/Many.java"
check "export-1.27 800 models: written, a class each" \
    [ "$rc" -eq 0 -a "$(grep -c 'static void add(final Scene scene)' "$tmp/Many.java")" -eq 800 ]
awk 'BEGIN { printf "model "; for (i = 0; i < 70000; i++) printf "n"; print ""
             printf "v 0 0 -1\nv 1 1 -1\nl 1 2\nmodel "
             for (i = 0; i < 12000; i++) printf "\360\235\204\236"; print ""
             printf "v 0 0 -1\nv 1 1 -1\nl 1 2\n" }' > "$tmp/longname.scene"
run export java "$tmp/longname.scene" -o "$tmp/LongName.java"
check "export-1.28 a 70,000-byte model name: joined from pieces" \
    [ "$rc" -eq 0 -a "$(grep -c 'String.join' "$tmp/LongName.java")" -eq 4 ]
i=0; while [ $i -lt 10001 ]; do echo "model m$i"; i=$((i + 1)); done > "$tmp/toomany.scene"
run export java "$tmp/toomany.scene" -o "$tmp/TooMany.java"
check "export-1.29 10,001 models: refused, exit 2, nothing written" \
    [ "$rc" -eq 2 -a ! -e "$tmp/TooMany.java" ]
check "export-1.30 ... saying the cap" grep -q 'more than 10000 would not compile' "$tmp/err"

# ----------------------------------------------------------------- export-2
if command -v javac > /dev/null 2>&1 && command -v java > /dev/null 2>&1; then
    s=$tmp/stub
    mkdir -p "$s/renderer/scene/primitives" "$s/renderer/scene/util" \
             "$s/renderer/framebuffer" "$s/renderer/pipeline"
    # The stub: renderer 4's signatures (javap of the jar), bodies that record.
    cat > "$s/renderer/scene/Scene.java" <<'JAVA'
package renderer.scene;
import java.util.*;
public final class Scene {
   public final String name; public final Camera camera; public boolean debug;
   public final List<Position> positionList = new ArrayList<>();
   public Scene(String name, Camera camera) { this.name = name; this.camera = camera; }
   public void addPosition(Position... ps) { positionList.addAll(Arrays.asList(ps)); }
}
JAVA
    cat > "$s/renderer/scene/Camera.java" <<'JAVA'
package renderer.scene;
public final class Camera {
   public final boolean perspective;
   private Camera(boolean p) { perspective = p; }
   public static Camera projPerspective() { return new Camera(true); }
   public static Camera projOrtho() { return new Camera(false); }
}
JAVA
    cat > "$s/renderer/scene/Vertex.java" <<'JAVA'
package renderer.scene;
public final class Vertex {
   public final double x, y, z;
   public Vertex(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
}
JAVA
    sed 's/Vertex/Vector/g' "$s/renderer/scene/Vertex.java" > "$s/renderer/scene/Vector.java"
    cat > "$s/renderer/scene/Model.java" <<'JAVA'
package renderer.scene;
import java.util.*;
import renderer.scene.primitives.Primitive;
public class Model {
   public final String name;
   public final List<Vertex> vertexList = new ArrayList<>();
   public final List<Primitive> primitiveList = new ArrayList<>();
   public final List<java.awt.Color> colorList = new ArrayList<>();
   public Model(String name) { this.name = name; }
   public final void addVertex(Vertex... vs) { vertexList.addAll(Arrays.asList(vs)); }
   public final void addPrimitive(Primitive... ps) { primitiveList.addAll(Arrays.asList(ps)); }
}
JAVA
    cat > "$s/renderer/scene/Position.java" <<'JAVA'
package renderer.scene;
public final class Position {
   public final String name; public final Model model; public final Vector t;
   public Position(Model m, String name, Vector t) { this.model = m; this.name = name; this.t = t; }
}
JAVA
    cat > "$s/renderer/scene/primitives/Primitive.java" <<'JAVA'
package renderer.scene.primitives;
import java.util.*;
public abstract class Primitive { public final List<Integer> vIndexList = new ArrayList<>(); }
JAVA
    cat > "$s/renderer/scene/primitives/LineSegment.java" <<'JAVA'
package renderer.scene.primitives;
public class LineSegment extends Primitive {
   public LineSegment(int a, int b) { vIndexList.add(a); vIndexList.add(b); }
}
JAVA
    cat > "$s/renderer/scene/util/ModelShading.java" <<'JAVA'
package renderer.scene.util;
import renderer.scene.Model;
public class ModelShading {
   public static void setColor(Model m, java.awt.Color c) {
      for (int i = 0; i < m.vertexList.size(); ++i) m.colorList.add(c);
   }
}
JAVA
    cat > "$s/renderer/framebuffer/FrameBuffer.java" <<'JAVA'
package renderer.framebuffer;
import java.awt.Color;
public final class FrameBuffer {
   public final int width, height; public Color bgColorFB; public final Viewport vp;
   public FrameBuffer(int w, int h, Color c) { width = w; height = h; bgColorFB = c; vp = new Viewport(); }
   public void setViewport(int x, int y, int w, int h) { vp.setViewport(x, y, w, h); }
   public void dumpFB2File(String f) { System.out.println("dump " + f); }
   public class Viewport {
      public int vp_ul_x, vp_ul_y, vp_lr_x, vp_lr_y;
      public void setViewport(int x, int y, int w, int h) {
         vp_ul_x = x; vp_ul_y = y; vp_lr_x = x + w - 1; vp_lr_y = y + h - 1;
      }
      public FrameBuffer getFrameBuffer() { return FrameBuffer.this; }
   }
}
JAVA
    cat > "$s/renderer/pipeline/Rasterize.java" <<'JAVA'
package renderer.pipeline;
public class Rasterize { public static boolean debug; }
JAVA
    cat > "$s/renderer/pipeline/Pipeline.java" <<'JAVA'
package renderer.pipeline;
import java.awt.Color;
import renderer.scene.*;
import renderer.scene.primitives.Primitive;
import renderer.framebuffer.FrameBuffer;
public final class Pipeline {
   static String b(double x) { return String.format("%016x", Double.doubleToRawLongBits(x)); }
   static String c(Color c) { return c.getRed() + " " + c.getGreen() + " " + c.getBlue(); }
   public static void render(Scene s, FrameBuffer.Viewport vp) {
      FrameBuffer fb = vp.getFrameBuffer();
      System.out.println("scene '" + s.name + "' perspective " + s.camera.perspective
                         + " debug " + s.debug + " pixels " + Rasterize.debug);
      for (Position p : s.positionList) {
         Model m = p.model;
         System.out.println("position " + p.name + " " + b(p.t.x) + " " + b(p.t.y) + " " + b(p.t.z));
         System.out.println("model " + m.name + " colors " + m.colorList.size()
                            + (m.colorList.isEmpty() ? "" : " " + c(m.colorList.get(0))));
         for (Vertex v : m.vertexList) System.out.println("v " + b(v.x) + " " + b(v.y) + " " + b(v.z));
         for (Primitive q : m.primitiveList) System.out.println("l " + q.vIndexList);
      }
      System.out.println("fb " + fb.width + " " + fb.height + " " + c(fb.bgColorFB) + " vp "
                         + vp.vp_ul_x + " " + vp.vp_ul_y + " " + vp.vp_lr_x + " " + vp.vp_lr_y);
   }
}
JAVA
    # What the stub must see: the bits of each double of odd.scene (python3 -c
    # "import struct; print(struct.pack('>d', 0.1).hex())" and so on).
    cat > "$tmp/want" <<'WANT'
scene '' perspective true debug true pixels true
position ẞ-𝄞 3fb999999999999a 8000000000000000 7e37e43c8800759c
model ẞ-𝄞 colors 3 1 2 3
v 3fb999999999999a 8000000000000000 7e37e43c8800759c
v 0000000000000001 3fd5555555555555 0011fa182c40c60d
v c0fe240c9fbe76c9 0000000000000000 3ff0000000000000
l [0, 1]
l [1, 2]
position empty 0000000000000000 0000000000000000 0000000000000000
model empty colors 0
fb 10 20 4 5 6 vp 1 2 3 5
dump out.ppm
WANT
    mkdir -p "$tmp/classes"
    javac -encoding UTF-8 -d "$tmp/classes" $(find "$s" -name '*.java') "$tmp/My_Scene2.java" \
        > "$tmp/javac" 2>&1
    check "export-2.1 the program compiles with javac against the API stub" [ $? -eq 0 ]
    (cd "$tmp" && LC_ALL=C.UTF-8 java -Dfile.encoding=UTF-8 -Dstdout.encoding=UTF-8 \
        -cp classes My_Scene2 out.ppm > "$tmp/got" 2>&1)
    check "export-2.2 ... and builds exactly the scene (doubles bit for bit)" cmp -s "$tmp/got" "$tmp/want"
    cmp -s "$tmp/got" "$tmp/want" || diff "$tmp/want" "$tmp/got" | head -10
    javac -encoding UTF-8 -d "$tmp/classes" -cp "$tmp/classes" "$tmp/Big.java" > "$tmp/javac" 2>&1
    check "export-2.3 1000 vertices compile" [ $? -eq 0 ]
    javac -encoding UTF-8 -d "$tmp/classes" -cp "$tmp/classes" "$tmp/Many.java" > "$tmp/javac" 2>&1
    check "export-2.4 800 models compile" [ $? -eq 0 ]
    grep -m3 error "$tmp/javac"
    javac -encoding UTF-8 -d "$tmp/classes" -cp "$tmp/classes" "$tmp/LongName.java" > "$tmp/javac" 2>&1
    check "export-2.5 model names of 70,000 bytes and 12,000 characters past U+FFFF compile" [ $? -eq 0 ]
    grep -m3 error "$tmp/javac"
    (cd "$tmp" && java -cp classes LongName > "$tmp/got" 2>&1)
    check "export-2.6 ... and reach the renderer whole" \
        [ "$(awk '$1 == "model" && $2 ~ /^n+$/ && length($2) == 70000' "$tmp/got" | wc -l)" -eq 1 ]
else
    echo "skipped: export-2 (the program compiles against a stub of the API): no javac and java"
fi

# ----------------------------------------------------------------- export-3
jar=${PIPETRACE_RENDERER4_JAR:-}
logs=tests/reference/kraftlog
[ -d "$logs" ] || logs=../shared/reference/kraftlog
if [ -z "$jar" ] || [ ! -f "$jar" ] || [ ! -d "$logs" ] || ! command -v javac > /dev/null 2>&1; then
    echo "skipped: export-3 (stderr equals the course's logs): needs a JDK," \
         "PIPETRACE_RENDERER4_JAR=renderer_4.jar and $logs"
else
    mkdir -p "$tmp/jar"
    for log in "$logs"/*.log; do
        name=$(basename "$log" .log)
        cls=C_$(echo "$name" | tr -c 'A-Za-z0-9\n' _)
        scene=$logs/../${name%.pixels}.scene
        case $name in *.pixels) px=--pixels ;; *) px= ;; esac
        "$exe" export java "$scene" -o "$tmp/jar/$cls.java" $px
    done
    javac -cp "$jar" -d "$tmp/jar" "$tmp"/jar/*.java > "$tmp/javac" 2>&1
    check "export-3.1 the programs of the reference scenes compile against the jar" [ $? -eq 0 ]
    for log in "$logs"/*.log; do
        name=$(basename "$log" .log)
        cls=C_$(echo "$name" | tr -c 'A-Za-z0-9\n' _)
        (cd "$tmp/jar" && java -cp "$jar:." "$cls" "$cls.ppm" > /dev/null 2> "$cls.err")
        check "export-3.2 $name: renderer 4's log of the exported scene is $log" \
            cmp -s "$tmp/jar/$cls.err" "$log"
        "$exe" "$logs/../${name%.pixels}.scene" --image "$tmp/jar/$cls.pt.ppm" > /dev/null
        check "export-3.3 $name: renderer 4's image is pipetrace's" \
            cmp -s "$tmp/jar/$cls.ppm" "$tmp/jar/$cls.pt.ppm"
    done
fi
report
