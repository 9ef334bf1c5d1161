// tests/data/JnumVectors.java -- test vectors for src/io/jnum.c (tests/unit/test_jnum.c).
// See LICENSE for copyright and license.
// Made with JDK 17, the course's Java (its Double.toString and Formatter's digits come from
// FloatingDecimal, not always the shortest; JDK 19 and later print other digits for a few):
//   java tests/data/JnumVectors.java > tests/data/jnum-vectors.txt
// Each line: the double's bits in hex, Double.toString, then String.format with
// "%.5f", "% 10.5f", "%9.4f", "%.4f", "%.2f", each field between '|'.
import java.util.Random;

public class JnumVectors {
    static void line(double x) {
        System.out.println(Long.toHexString(Double.doubleToRawLongBits(x)) + "|" + Double.toString(x)
            + "|" + String.format("%.5f", x) + "|" + String.format("% 10.5f", x)
            + "|" + String.format("%9.4f", x) + "|" + String.format("%.4f", x)
            + "|" + String.format("%.2f", x));
    }
    public static void main(String[] a) {
        double[] fixed = {0.0, -0.0, 1.0, -1.0, 0.5, 0.125, 0.375, -0.125, 2.5e-6, 1.0e-5,
            1.0e-3, 9.999999999999998e-4, 1.0e7, 9999999.999999998, 1.0e23, 2.0e23, 5e-324,
            1.0e-323, Double.MIN_NORMAL, Double.MAX_VALUE, Math.pow(2, -44), 0.1, 0.2, 0.3,
            1.0 / 3, 2.0 / 3, 4.35, 0.000015, 0.0000149999, 123456.789, 99999.999995,
            9.999995, 0.999995, 0.54998, 1.44953, 12345.123455, 1e300, -1e-300,
            Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
            2.0 / 2.001, 320 / 2.001, 0.5 + 240 / 2.001 * 0.875};
        for (double x : fixed) line(x);
        for (int p = -60; p <= 60; p++) { line(Math.pow(2, p)); line(Math.pow(10, p)); }
        for (int n = -40; n <= 40; n++)          // slopes: ratios of small integers
            for (int d = 1; d <= 40; d += 3) line((double) n / d);
        for (int k = 0; k < 400; k++) line(k / 8.0 + 0.00000500000001 * (k % 3));
        Random r = new Random(12);
        for (int k = 0; k < 1500; k++) {
            double m = r.nextDouble() * 2 - 1;
            line(m * Math.pow(10, r.nextInt(24) - 12));
        }
        for (int k = 0; k < 500; k++) line(Double.longBitsToDouble(r.nextLong()));
        for (int k = 0; k < 400; k++) {         // five decimals and a half, as typed
            long v = r.nextInt(2000000) - 1000000;
            line(Double.parseDouble(String.format("%d.%05d5", v / 100000, Math.abs(v % 100000))));
        }
    }
}
