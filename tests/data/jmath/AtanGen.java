// tests/data/jmath/AtanGen.java -- Java's Math.atan for tests/data/jmath/atan.txt (not needed by make test).
// See LICENSE for copyright and license.
// Run with JDK 17: javac AtanGen.java && java AtanGen atan.bin 4000000.  Writes pairs
// (x, Math.atan(x)) as big-endian longs: special values, the reduction thresholds of fdlibm's
// s_atan.c with their neighbours, then random doubles (random bits, several exponents, |x| < 3,
// three decimals); reports how often Math.atan and StrictMath.atan differ (0 on JDK 17).
import java.io.*;
import java.util.*;
public class AtanGen {
    static DataOutputStream out; static long mism = 0;
    static void emit(double x) throws IOException {
        double a = Math.atan(x), s = StrictMath.atan(x);
        if (Double.doubleToRawLongBits(a) != Double.doubleToRawLongBits(s) && !(Double.isNaN(a) && Double.isNaN(s))) mism++;
        out.writeLong(Double.doubleToRawLongBits(x)); out.writeLong(Double.doubleToRawLongBits(a));
    }
    public static void main(String[] args) throws IOException {
        out = new DataOutputStream(new BufferedOutputStream(new FileOutputStream(args[0]), 1<<20));
        int n = Integer.parseInt(args[1]);
        Random r = new Random(12345);
        double[] special = {0.0, -0.0, Double.MIN_VALUE, -Double.MIN_VALUE, Double.MIN_NORMAL, Double.MAX_VALUE, -Double.MAX_VALUE,
            Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN, 0x1p66, -0x1p66, Math.nextDown(0x1p66), 0x1p-29, Math.nextDown(0x1p-29),
            7.0/16, 11.0/16, 19.0/16, 39.0/16, 1e300, 1, -1, 0.5, 1.5, 2, 0x1p67, 0x1p100};
        for (double d : special) { emit(d); emit(Math.nextUp(d)); emit(Math.nextDown(d)); emit(-d); }
        // thresholds on high words
        int[] hw = {0x44100000, 0x3fdc0000, 0x3e200000, 0x3ff30000, 0x3fe60000, 0x40038000};
        for (int h : hw) for (long lo = -3; lo <= 3; lo++) { long b = ((long)h << 32) + lo; emit(Double.longBitsToDouble(b)); emit(-Double.longBitsToDouble(b)); }
        for (int i = 0; i < n; i++) {
            double x;
            switch (i % 4) {
            case 0: x = Double.longBitsToDouble(r.nextLong()); break;
            case 1: x = (r.nextDouble() * 2 - 1) * Math.pow(2, r.nextInt(140) - 70); break;
            case 2: x = (r.nextDouble() * 6 - 3); break;
            default: x = r.nextInt(20001) / 1000.0 - 10; break;
            }
            emit(x);
        }
        out.close();
        System.err.println("Math vs StrictMath mismatches: " + mism);
    }
}
