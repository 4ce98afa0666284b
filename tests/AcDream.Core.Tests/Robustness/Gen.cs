using System.Numerics;

namespace AcDream.Core.Tests.Robustness;

/// <summary>Seeded random inputs for the property tests.</summary>
internal static class Gen
{
    public static float Range(Random random, double min, double max) => (float)(min + (random.NextDouble() * (max - min)));

    /// <summary>A random 256-entry height table: linear, the game-like quadratic, or random monotone / non-monotone steps, all within ±2000 m.</summary>
    public static float[] HeightTable(Random random)
    {
        var table = new float[256];
        int kind = random.Next(4);
        double scale = random.NextDouble() * 4;
        double offset = Range(random, -200, 200);
        double z = offset;
        for (int i = 0; i < 256; i++)
        {
            table[i] = kind switch
            {
                0 => (float)(offset + (scale * i)),                                   // linear
                1 => (float)(offset + (0.5 * i) + (0.02 * i * i)),                    // game-like, coarse at the top
                2 => (float)(z += random.NextDouble() * 6),                            // random monotone
                _ => Range(random, -500, 1500),                                       // arbitrary
            };
        }

        return table;
    }

    /// <summary>Random heights: noise, smooth hills, or flat.</summary>
    public static byte[] Heights(Random random)
    {
        var heights = new byte[81];
        switch (random.Next(3))
        {
            case 0:
                random.NextBytes(heights);
                break;
            case 1:
                double fx = random.NextDouble(), fy = random.NextDouble(), a = random.Next(20, 120), b = random.Next(0, 120);
                for (int i = 0; i < 81; i++)
                {
                    heights[i] = (byte)Math.Clamp(b + (a * Math.Sin((fx * (i / 9)) + (fy * (i % 9)))), 0, 255);
                }

                break;
            default:
                Array.Fill(heights, (byte)random.Next(256));
                break;
        }

        return heights;
    }

    /// <summary>A rotation about Z by a random angle (a quarter of them a multiple of 90°), optionally stored slightly non-unit and slightly tilted.</summary>
    public static Quaternion Orientation(Random random, bool sloppy)
    {
        double degrees = random.Next(4) == 0 ? 90 * random.Next(4) : random.NextDouble() * 360;
        Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (float)(degrees * Math.PI / 180));
        if (sloppy)
        {
            q = new Quaternion(q.X + Range(random, -1e-4, 1e-4), q.Y + Range(random, -1e-4, 1e-4), q.Z, q.W) * Range(random, 0.99, 1.01);
        }

        return q;
    }

    /// <summary>
    /// A random physics polygon (cell-local): a convex n-gon on a plane of random slope (floors and
    /// too-steep ones), sometimes reversed (a ceiling), a vertical wall, a non-planar quad, or one
    /// with a duplicated or collinear vertex.
    /// </summary>
    public static Vector3[] Polygon(Random random, float extent)
    {
        float cx = Range(random, -extent, extent), cy = Range(random, -extent, extent), z0 = Range(random, -3, 3);
        int kind = random.Next(10);
        if (kind == 0)
        {
            float x1 = cx + Range(random, -4, 4), y1 = cy + Range(random, -4, 4);
            return TestData.Wall(cx, cy, x1, y1, z0, z0 + 2.5f);
        }

        float gx = Range(random, -1.2, 1.2), gy = Range(random, -1.2, 1.2);
        if (random.Next(3) == 0)
        {
            gx = gy = 0f;
        }

        int n = kind == 1 ? 4 : random.Next(3, 13);
        double rx = Range(random, 0.3, 6), ry = Range(random, 0.3, 6), phase = random.NextDouble() * 2 * Math.PI;
        var angles = Enumerable.Range(0, n).Select(_ => random.NextDouble() * 2 * Math.PI).Order().ToArray();
        var vertices = new List<Vector3>();
        foreach (double t in angles)
        {
            float x = cx + (float)(rx * Math.Cos(t + phase)), y = cy + (float)(ry * Math.Sin(t + phase));
            float z = z0 + (gx * (x - cx)) + (gy * (y - cy));
            if (kind == 1)
            {
                z += Range(random, -0.3, 0.3); // non-planar
            }

            vertices.Add(new Vector3(x, y, z));
        }

        if (kind == 2 && vertices.Count > 2)
        {
            vertices.Insert(1, vertices[1]); // duplicated vertex
        }
        else if (kind == 3 && vertices.Count > 2)
        {
            vertices.Insert(1, Vector3.Lerp(vertices[0], vertices[1], 0.5f)); // collinear vertex
        }

        if (random.Next(6) == 0)
        {
            vertices.Reverse(); // faces down
        }

        return [.. vertices];
    }
}
