// tests/bench/BenchKraft.java -- time the course's Java renderer 4, 7 or 9 rendering a bench scene
// See LICENSE for copyright and license.
//
// Usage (tests/bench/bench.c compiles it against the course's jar):
//   java -cp JAR:CLASSES BenchKraft CASE RUNS
// Reads a case file of tests/bench/benchgen.c (`benchgen N PER R [aa] case`:
// fb, camera persp, aa, gamma, model, t, c, v, l; debug and comments are
// skipped), builds the scene through the renderer's public API as the
// course's harnesses do, then renders it RUNS times with Pipeline.render
// into a cleared framebuffer and prints "render S": the least CPU seconds of
// this thread over the runs (the first ones are the JIT compiler's: the least
// is a warm one, as bench.c's own renders are).
import renderer.scene.*;
import renderer.scene.primitives.*;
import renderer.pipeline.*;
import renderer.framebuffer.*;
import java.awt.Color;
import java.io.*;
import java.lang.management.*;
import java.util.*;

public class BenchKraft {
  public static void main(String[] args) throws IOException {
    int w = 0, h = 0, runs = Integer.parseInt(args[1]);
    List<Position> positions = new ArrayList<>();
    Position pos = null;
    Model model = null;
    try (BufferedReader r = new BufferedReader(new FileReader(args[0]))) {
      for (String line; (line = r.readLine()) != null; ) {
        String[] f = line.trim().split("\\s+");
        switch (f[0]) {
          case "fb": w = Integer.parseInt(f[1]); h = Integer.parseInt(f[2]); break;
          case "aa": Rasterize.doAntiAliasing = !f[1].equals("0"); break;
          case "gamma": Rasterize.doGamma = !f[1].equals("0"); break;
          case "model":
            model = new Model(f[1]);
            pos = new Position(model, f[1]);
            positions.add(pos);
            break;
          case "t": pos.translate(d(f[1]), d(f[2]), d(f[3])); break;
          case "c": model.addColor(new Color(i(f[1]), i(f[2]), i(f[3]))); break;
          case "v": model.addVertex(new Vertex(d(f[1]), d(f[2]), d(f[3]))); break;
          case "l": model.addPrimitive(new LineSegment(i(f[1]), i(f[2]))); break;
          default: break;                       // camera persp (the default), debug, comments
        }
      }
    }
    Scene scene = new Scene("bench", Camera.projPerspective());
    for (Position p : positions) scene.addPosition(p);
    ThreadMXBean mx = ManagementFactory.getThreadMXBean();
    long least = Long.MAX_VALUE;
    for (int k = 0; k < runs; k++) {
      FrameBuffer fb = new FrameBuffer(w, h, Color.black);
      long t0 = mx.getCurrentThreadCpuTime();
      fb.vp.clearVP();
      Pipeline.render(scene, fb.vp);
      least = Math.min(least, mx.getCurrentThreadCpuTime() - t0);
    }
    System.out.printf(Locale.ROOT, "render %.6f%n", least / 1e9);
  }

  static int i(String s) { return Integer.parseInt(s); }
  static double d(String s) { return Double.parseDouble(s); }
}
