// tests/data/JnumHard.java -- doubles for tests/data/jnum-hard.txt (not needed by make test).
// See LICENSE for copyright and license.
// java JnumHard.java KIND N SEED prints N lines "bits Double.toString String.format(%.20e)"
// for KIND special (powers of two and ten with neighbours, small integers, subnormals, ratios;
// N and SEED unused), bits (random bits), dec (random decimals), int (random longs).
// Run on JDK 17 and on JDK 19 or later and keep the lines whose toString differ:
//   paste -d' ' j17.txt j25.txt | awk '($2"") != ($4"") { print $1 "|" $2 }'
// The %.20e column shows Formatter's digits (JDK 17: FloatingDecimal's, not always shortest).
import java.io.*;
import java.util.*;
public class JnumHard {
    static PrintStream out;
    static void emit(double x) {
        out.print(Long.toHexString(Double.doubleToRawLongBits(x)));
        out.print(' ');
        out.print(Double.toString(x));
        out.print(' ');
        out.print(String.format("%.20e", x));
        out.print('\n');
    }
    public static void main(String[] a) throws Exception {
        out = new PrintStream(new BufferedOutputStream(new FileOutputStream(FileDescriptor.out), 1 << 20), false, "US-ASCII");
        String kind = a[0]; int n = Integer.parseInt(a[1]); long seed = Long.parseLong(a[2]);
        Random r = new Random(seed);
        if (kind.equals("special")) {
            for (int e = -1074; e <= 1023; e++) { double p = Math.scalb(1.0, e); emit(p); emit(Math.nextUp(p)); emit(Math.nextDown(p)); }
            for (int e = -325; e <= 308; e++) { double p = Double.parseDouble("1e" + e); emit(p); emit(Math.nextUp(p)); emit(Math.nextDown(p)); }
            for (long i = 1; i < 100000; i++) emit(i);
            for (long i = 0; i < 100000; i++) emit(Double.longBitsToDouble(i));
            for (int nn = -100; nn <= 100; nn++) for (int d = 1; d <= 200; d++) emit((double) nn / d);
            double[] s = {Double.MIN_VALUE, Double.MIN_NORMAL, Double.MAX_VALUE, 1e23, 2e-3, 0x1p-31, 0x1p60, 1e7, 9999999.999999998, 1e-3, 9.999999999999998e-4};
            for (double x : s) { emit(x); emit(Math.nextUp(x)); emit(Math.nextDown(x)); }
            out.flush();
            return;
        }
        for (int i = 0; i < n; i++) {
            double x;
            switch (kind) {
            case "bits": x = Double.longBitsToDouble(r.nextLong() & 0x7fffffffffffffffL); if (Double.isNaN(x) || Double.isInfinite(x) || x == 0) continue; break;
            case "dec": {
                int nd = 1 + r.nextInt(17);
                long m = (long)(r.nextDouble() * Math.pow(10, nd)); if (m == 0) m = 1;
                int e = r.nextInt(60) - 30;
                if (r.nextInt(10) == 0) e = r.nextInt(640) - 330;
                x = Double.parseDouble(m + "e" + e); if (x == 0 || Double.isInfinite(x)) continue; break; }
            case "int": x = (double)(r.nextLong() >>> r.nextInt(64)); if (x == 0) continue; break;
            case "mid": x = (r.nextDouble()) * Math.pow(2, r.nextInt(100) - 50); if (x == 0) continue; break;
            default: throw new RuntimeException(kind);
            }
            emit(x);
        }
        out.flush();
    }
}
