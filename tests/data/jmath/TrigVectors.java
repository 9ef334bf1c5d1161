// tests/data/jmath/TrigVectors.java -- Java's Math.sin, Math.cos and Math.tan of the course's angles
// for tests/data/jmath/trig.txt (not needed by make test).  See LICENSE for copyright and license.
// Run with JDK 17 (HotSpot, x86_64: these three are intrinsics, Intel's libm, neither fdlibm nor
// glibc):  java TrigVectors.java > trig.txt.  Each line: the angle in degrees (an integer
// -720..720), then the bits in hex of Math.sin(a), Math.cos(a) with a = (Math.PI/180.0)*deg, as
// renderer 9's rotate computes them, and of Math.tan(((Math.PI/180.0)*deg)/2.0), renderers 7 and
// 9's top for projPerspective(fovy = deg, ...).
public class TrigVectors {
    public static void main(String[] x) {
        System.out.println("# tests/data/jmath/trig.txt -- deg, JDK 17 Math.sin, Math.cos of (PI/180)*deg and Math.tan of");
        System.out.println("# ((PI/180)*deg)/2, the bits in hex.  Made by tests/data/jmath/TrigVectors.java.");
        for (int d = -720; d <= 720; d++) {
            double a = (Math.PI/180.0)*d;
            System.out.println(d + " " + Long.toHexString(Double.doubleToRawLongBits(Math.sin(a))) + " "
                + Long.toHexString(Double.doubleToRawLongBits(Math.cos(a))) + " "
                + Long.toHexString(Double.doubleToRawLongBits(Math.tan(((Math.PI/180.0)*d)/2.0))));
        }
    }
}
