// tests/data/shapes/ShapeDump.java -- print a course model's vertices and segments
// See LICENSE for copyright and license.
//
// Run against the course's renderer 4 jar (make.sh in this folder does it):
//   java -cp renderer_4.jar:. ShapeDump NAME ARGS...
// prints "# shape NAME ARGS", then "v X Y Z" per vertex (Double.toString, which
// reads back exactly) and "l I J" per line segment (0-based), in the model's order.
import renderer.scene.Model;
import renderer.scene.Vertex;
import renderer.scene.primitives.Primitive;
import renderer.models_L.*;

public class ShapeDump
{
   static double d(String[] a, int i) { return Double.parseDouble(a[i]); }
   static int i(String[] a, int i) { return Integer.parseInt(a[i]); }

   static Model make(String[] a)
   {
      final int n = a.length - 1;
      switch (a[0])
      {
         case "sphere":
            return n == 0 ? new Sphere() : n == 1 ? new Sphere(d(a,1))
                 : new Sphere(d(a,1), i(a,2), i(a,3));
         case "cylinder":
            return n == 0 ? new Cylinder() : n == 2 ? new Cylinder(d(a,1), d(a,2))
                 : new Cylinder(d(a,1), d(a,2), i(a,3), i(a,4));
         case "cone":
            return n == 0 ? new Cone() : n == 2 ? new Cone(d(a,1), d(a,2))
                 : new Cone(d(a,1), d(a,2), i(a,3), i(a,4));
         case "torus":
            return n == 0 ? new Torus() : n == 2 ? new Torus(d(a,1), d(a,2))
                 : new Torus(d(a,1), d(a,2), i(a,3), i(a,4));
         case "disk":
            return n == 0 ? new Disk() : n == 1 ? new Disk(d(a,1))
                 : new Disk(d(a,1), i(a,2), i(a,3));
         case "ring":
            return n == 0 ? new Ring() : n == 2 ? new Ring(d(a,1), d(a,2))
                 : new Ring(d(a,1), d(a,2), i(a,3), i(a,4));
         case "circle":
            return n == 0 ? new Circle() : n == 1 ? new Circle(d(a,1))
                 : new Circle(d(a,1), i(a,2));
         case "square":
            return n == 0 ? new Square() : new Square(d(a,1));
         case "squaregrid":
            return n == 0 ? new SquareGrid() : n == 1 ? new SquareGrid(d(a,1))
                 : n == 2 ? new SquareGrid(d(a,1), i(a,2))
                 : new SquareGrid(d(a,1), i(a,2), i(a,3));
         case "cube": return new Cube();
         case "box":
            return n == 0 ? new Box() : new Box(d(a,1), d(a,2), d(a,3));
         case "tetrahedron": return new Tetrahedron();
         case "octahedron": return new Octahedron();
         case "dodecahedron": return new Dodecahedron();
         case "icosahedron": return new Icosahedron();
         case "icosidodecahedron": return new Icosidodecahedron();
         case "pyramid":
            return n == 0 ? new Pyramid() : n == 2 ? new Pyramid(d(a,1), d(a,2))
                 : new Pyramid(d(a,1), d(a,2), i(a,3), i(a,4));
         case "axes3d":
            return n == 0 ? new Axes3D() : new Axes3D(d(a,1), d(a,2), d(a,3));
      }
      throw new IllegalArgumentException("unknown shape " + a[0]);
   }

   public static void main(String[] args)
   {
      final StringBuilder out = new StringBuilder("# shape");
      for (String s : args) out.append(' ').append(s);
      out.append('\n');
      try
      {
         final Model m = make(args);
         for (Vertex v : m.vertexList)
            out.append("v ").append(v.x).append(' ').append(v.y).append(' ').append(v.z).append('\n');
         for (Primitive p : m.primitiveList)
            out.append("l ").append(p.vIndexList.get(0)).append(' ').append(p.vIndexList.get(1)).append('\n');
      }
      catch (IllegalArgumentException e)
      {
         out.append("error ").append(e.getMessage()).append('\n');
      }
      System.out.print(out);
   }
}
