#!/bin/sh
# tests/cli/export.sh -- pipetrace export java
# See LICENSE for copyright and license.
#
# Usage: sh tests/cli/export.sh PIPETRACE
#   export-1  arguments, class names, errors, files written whole or not at all
#   export-2  (with a JDK) the program compiles against a stub of the course
#             renderers' API (4, 7 and 9 together) that this script writes,
#             and hands the stub exactly the scene's doubles, names, indices,
#             colors and sizes; for renderers 7 and 9 the camera's parameters,
#             near, view, the switches and debug flags, Pipeline2, the
#             position's matrix operations in order, colour lists, points
#             and hidden flags (tests/course/export-check.sh runs the
#             programs of the course corpus against the real jars)
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
run export java "$tmp/odd.scene" --debug scene,bogus
check "export-1.31 --debug with a name that is no switch: usage error" [ "$rc" -eq 1 ]
check "export-1.31 ... naming the switches" grep -q 'scene, position, rasterize, clip, nearclip' "$tmp/err"
run export java "$tmp/odd.scene" --debug none
check "export-1.32 --debug none: scene.debug off" grep -qF 'scene.debug = false;' "$tmp/out"
run export java "$tmp/odd.scene" --debug position,rasterize
check "export-1.33 --debug position,rasterize: every Position.debug" \
    grep -qF 'for (final Position p : scene.positionList) p.debug = true;' "$tmp/out"
check "export-1.33 ... and Rasterize.debug, renderer 4: no NearClip" \
    sh -c "grep -qF 'Rasterize.debug = true;' '$tmp/out' && ! grep -q NearClip '$tmp/out'"
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
for c in M1Vertices0 M1 M12Segments3 M1Colors0 M2Matrices1; do
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
   public final boolean perspective; public final String d;
   private Camera(boolean p, String d) { perspective = p; this.d = d; }
   public static Camera projPerspective() { return new Camera(true, "persp()"); }
   public static Camera projOrtho() { return new Camera(false, "ortho()"); }
   public static Camera projPerspective(double l, double r, double b, double t) { return new Camera(true, "persp(" + l + "," + r + "," + b + "," + t + ")"); }
   public static Camera projOrtho(double l, double r, double b, double t) { return new Camera(false, "ortho(" + l + "," + r + "," + b + "," + t + ")"); }
   public Camera changeNear(double n) { return new Camera(perspective, d + ".near(" + n + ")"); }
   public Camera translate(double x, double y, double z) { return new Camera(perspective, d + ".view(" + x + "," + y + "," + z + ")"); }
}
JAVA
    cat > "$s/renderer/scene/Vertex.java" <<'JAVA'
package renderer.scene;
public final class Vertex {
   public final double x, y, z;
   public Vertex(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
}
JAVA
    cat > "$s/renderer/scene/Vector.java" <<'JAVA'
package renderer.scene;
public final class Vector {
   public final double x, y, z, w;
   public Vector(double x, double y, double z) { this(x, y, z, 0.0); }
   public Vector(double x, double y, double z, double w) { this.x = x; this.y = y; this.z = z; this.w = w; }
}
JAVA
    cat > "$s/renderer/scene/Model.java" <<'JAVA'
package renderer.scene;
import java.util.*;
import renderer.scene.primitives.Primitive;
public class Model {
   public final String name;
   public final List<Vertex> vertexList = new ArrayList<>();
   public final List<Primitive> primitiveList = new ArrayList<>();
   public final List<java.awt.Color> colorList = new ArrayList<>();
   public boolean visible = true;
   public Model(String name) { this.name = name; }
   public final void addColor(java.awt.Color... cs) { colorList.addAll(Arrays.asList(cs)); }
   public final void addVertex(Vertex... vs) { vertexList.addAll(Arrays.asList(vs)); }
   public final void addPrimitive(Primitive... ps) { primitiveList.addAll(Arrays.asList(ps)); }
}
JAVA
    cat > "$s/renderer/scene/Position.java" <<'JAVA'
package renderer.scene;
public final class Position {
   public final String name; public final Model model; public final Vector t;
   public boolean visible = true, debug; private Matrix matrix = Matrix.identity();
   public Position(Model m, String name, Vector t) { this.model = m; this.name = name; this.t = t; }
   public Position(Model m, String name) { this(m, name, new Vector(0, 0, 0)); }
   public Matrix getMatrix() { return matrix; }
   public Position transform(Matrix m) { matrix = m; return this; }
}
JAVA
    cat > "$s/renderer/scene/primitives/Primitive.java" <<'JAVA'
package renderer.scene.primitives;
import java.util.*;
public abstract class Primitive {
   public final List<Integer> vIndexList = new ArrayList<>(), cIndexList = new ArrayList<>();
}
JAVA
    cat > "$s/renderer/scene/primitives/LineSegment.java" <<'JAVA'
package renderer.scene.primitives;
public class LineSegment extends Primitive {
   public LineSegment(int a, int b) { this(a, b, a, b); }
   public LineSegment(int a, int b, int c, int d) {
      vIndexList.add(a); vIndexList.add(b); cIndexList.add(c); cIndexList.add(d);
   }
}
JAVA
    cat > "$s/renderer/scene/primitives/Point.java" <<'JAVA'
package renderer.scene.primitives;
public class Point extends Primitive {
   public int radius = 0;
   public Point(int v) { this(v, v); }
   public Point(int v, int c) { vIndexList.add(v); cIndexList.add(c); }
}
JAVA
    # renderers 7 and 9: the camera's parameters, Matrix; each records what built it
    cat > "$s/renderer/scene/Matrix.java" <<'JAVA'
package renderer.scene;
public final class Matrix {
   final String d;
   Matrix(String d) { this.d = d; }
   static String b(double x) { return Long.toHexString(Double.doubleToRawLongBits(x)); }
   public static Matrix identity() { return new Matrix("I"); }
   public static Matrix translate(double x, double y, double z) { return new Matrix("T(" + b(x) + "," + b(y) + "," + b(z) + ")"); }
   public static Matrix scale(double x, double y, double z) { return new Matrix("S(" + x + "," + y + "," + z + ")"); }
   public static Matrix rotate(double t, double x, double y, double z) { return new Matrix("R(" + t + "," + x + "," + y + "," + z + ")"); }
   public static Matrix buildFromRows(Vector a, Vector b, Vector c, Vector e) {
      return new Matrix("Rows(" + a.w + "," + b.x + "," + c.y + "," + e.z + "," + e.w + ")");
   }
   public Matrix times(Matrix m) { return new Matrix("(" + d + "*" + m.d + ")"); }
   public String toString() { return d; }
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
   public final int width, height; public Color bgColorFB; public final Viewport vp; public String bgVP = "";
   public FrameBuffer(int w, int h, Color c) { width = w; height = h; bgColorFB = c; vp = new Viewport(); }
   public void setViewport(int x, int y, int w, int h) { vp.setViewport(x, y, w, h); }
   public void dumpFB2File(String f) { System.out.println("dump " + f); }
   public class Viewport {
      public int vp_ul_x, vp_ul_y, vp_lr_x, vp_lr_y;
      public void setViewport(int x, int y, int w, int h) {
         vp_ul_x = x; vp_ul_y = y; vp_lr_x = x + w - 1; vp_lr_y = y + h - 1;
      }
      public FrameBuffer getFrameBuffer() { return FrameBuffer.this; }
      public void setBackgroundColorVP(Color c) { bgVP += " bgVP " + c.getRGB(); }
      public void clearVP() { bgVP += " cleared"; }
   }
}
JAVA
    cat > "$s/renderer/pipeline/Rasterize.java" <<'JAVA'
package renderer.pipeline;
public class Rasterize { public static boolean debug, doAntiAliasing, doGamma = true; }
JAVA
    cat > "$s/renderer/pipeline/NearClip.java" <<'JAVA'
package renderer.pipeline;
public class NearClip { public static boolean debug, doNearClipping = true; }
JAVA
    cat > "$s/renderer/pipeline/Clip.java" <<'JAVA'
package renderer.pipeline;
public class Clip { public static boolean debug; }
JAVA
    cat > "$s/renderer/pipeline/Pipeline2.java" <<'JAVA'
package renderer.pipeline;
public final class Pipeline2 {
   public static void render(renderer.scene.Scene s, renderer.framebuffer.FrameBuffer.Viewport vp) {
      System.out.println("Pipeline2");
      Pipeline.render(s, vp);
   }
}
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
      if (System.getProperty("stub.full") == null)
         return;
      System.out.println("camera " + s.camera.d + fb.bgVP + " nearclip " + NearClip.doNearClipping
                         + " aa " + Rasterize.doAntiAliasing + " gamma " + Rasterize.doGamma
                         + " clipdebug " + Clip.debug + " nearclipdebug " + NearClip.debug);
      for (Position p : s.positionList) {
         Model m = p.model;
         System.out.println("position " + p.name + " matrix " + p.getMatrix() + " visible " + p.visible
                            + " " + m.visible + " debug " + p.debug);
         for (Color k : m.colorList) {
            float[] f = k.getRGBComponents(null);
            System.out.println("c " + Integer.toHexString(k.getRGB()) + " " + f[0] + " " + f[1] + " " + f[2]);
         }
         for (Primitive q : m.primitiveList)
            System.out.println((q instanceof renderer.scene.primitives.Point
                                ? "p radius " + ((renderer.scene.primitives.Point)q).radius + " " : "l ")
                               + q.vIndexList + " " + q.cIndexList);
      }
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
    # the course's renderers 7 and 9: every directive reaches the API
    cat > "$tmp/r9.scene" <<'SCENE'
renderer 9
scene nine
framebuffer 30 20
background 1 2 3
viewport 2 3 20 10
viewport-background 7 8 9
camera perspective -2 1 -0.5 1.5 2
near 0.5
view 0.25 -0.5 1
nearclip off
antialias on
gamma off
pipeline2
model cube pos
translate 0.5 0 -3
matrix rotate y 30
matrix-pre scale 2
matrix scale 1 2 0.5
matrix rotate 45 0 0 1
matrix rows 1 0 0 0.5  0 1 0 0  0 0 1 0  0.25 0 0 2
v 0 0 0
v 1 1 1
v 0.5 0.25 -1
vcolor 10 20 30
vcolor-float 0.3 0.6 0.9
vcolor 255 0 128
segment 1 2
point 3 2 2
segment 2 3 3 1
point 1
l 1 3
hidden-position
model two
color 4 5 6
v 0 0 -1
point 1 1 -1
hidden-model
SCENE
    cat > "$tmp/want9" <<'WANT'
Pipeline2
scene 'nine' perspective true debug true pixels true
position pos 0000000000000000 0000000000000000 0000000000000000
model cube colors 3 10 20 30
v 0000000000000000 0000000000000000 0000000000000000
v 3ff0000000000000 3ff0000000000000 3ff0000000000000
v 3fe0000000000000 3fd0000000000000 bff0000000000000
l [0, 1]
l [2]
l [1, 2]
l [0]
l [0, 2]
position two 0000000000000000 0000000000000000 0000000000000000
model two colors 1 4 5 6
v 0000000000000000 0000000000000000 bff0000000000000
l [0]
fb 30 20 1 2 3 vp 2 3 21 12
camera persp(-1.0,0.5,-0.25,0.75).near(0.5).view(0.25,-0.5,1.0) bgVP -16316407 cleared nearclip false aa true gamma false clipdebug true nearclipdebug true
position pos matrix ((((S(2.0,2.0,2.0)*(T(3fe0000000000000,0,c008000000000000)*R(30.0,0.0,1.0,0.0)))*S(1.0,2.0,0.5))*R(45.0,0.0,0.0,1.0))*Rows(0.5,0.0,0.0,0.0,2.0)) visible false true debug true
c ff0a141e 0.039215688 0.078431375 0.11764706
c ff4d99e6 0.3 0.6 0.9
c ffff0080 1.0 0.0 0.5019608
l [0, 1] [0, 1]
p radius 2 [2] [1]
l [1, 2] [2, 0]
p radius 0 [0] [0]
l [0, 2] [0, 2]
position two matrix I visible true false debug true
c ff040506 0.015686275 0.019607844 0.023529412
p radius -1 [0] [0]
dump out.ppm
WANT
    run export java "$tmp/r9.scene" --debug all -o "$tmp/Nine.java"
    check "export-2.7 renderer 9, --debug all: written" [ "$rc" -eq 0 ]
    javac -encoding UTF-8 -d "$tmp/classes" -cp "$tmp/classes" "$tmp/Nine.java" > "$tmp/javac" 2>&1
    check "export-2.7 ... compiles" [ $? -eq 0 ]
    grep -m3 error "$tmp/javac"
    (cd "$tmp" && java -Dstub.full=1 -cp classes Nine out.ppm > "$tmp/got" 2>&1)
    check "export-2.8 ... and builds the scene: camera, near, view, switches, debug flags, Pipeline2, matrices in order, colour lists, primitives in file order, hidden flags" \
        cmp -s "$tmp/got" "$tmp/want9"
    cmp -s "$tmp/got" "$tmp/want9" || diff "$tmp/want9" "$tmp/got" | head -10
    printf 'renderer 7\nframebuffer 8 8\ncamera orthographic-fov 90 2\nnear 0.5\nmodel m\nv 0 0 -1\nv 1 0 -1\nsegment 1 2\n' > "$tmp/r7.scene"
    run export java "$tmp/r7.scene" -o "$tmp/Seven.java"
    javac -encoding UTF-8 -d "$tmp/classes" -cp "$tmp/classes" "$tmp/Seven.java" > "$tmp/javac" 2>&1
    check "export-2.9 renderer 7: compiles" [ $? -eq 0 ]
    (cd "$tmp" && java -Dstub.full=1 -cp classes Seven out.ppm > "$tmp/got" 2>&1)
    check "export-2.10 ... the fov camera as its view rectangle, near as changeNear, no matrix" \
        grep -qx 'camera ortho(-1.9999999999999998,1.9999999999999998,-0.9999999999999999,0.9999999999999999).near(0.5) cleared nearclip true aa false gamma true clipdebug false nearclipdebug false' "$tmp/got"
    check "export-2.11 ... the position's translation a Vector, no colours (the course adds white)" \
        grep -qx 'model m colors 0' "$tmp/got"
    # near 0 is changeNear(0.0): n = -0.0, the camera plane (tests/course/r7/near-edge-00)
    sed 's/^near 0.5$/near 0/' "$tmp/r7.scene" > "$tmp/r7zero.scene"
    run export java "$tmp/r7zero.scene" -o "$tmp/Zero.java"
    javac -encoding UTF-8 -d "$tmp/classes" -cp "$tmp/classes" "$tmp/Zero.java" > "$tmp/javac" 2>&1
    (cd "$tmp" && java -Dstub.full=1 -cp classes Zero out.ppm > "$tmp/got" 2>&1)
    check "export-2.12 near 0: changeNear(0.0), not changeNear(-0.0)" grep -q '\.near(0\.0) ' "$tmp/got"
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
