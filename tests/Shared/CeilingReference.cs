using static AcDream.Testing.ReferenceBody;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced).

/// <summary>
/// What a rising body's top meets, in double precision by brute force: the lowest point of any polygon over the disc
/// of the body seen from above, sampled on rings of the disc (for polygons that are not vertical, on their planes) and
/// along the polygons' edges, among those at or above the top. Landblock-local metres.
/// </summary>
internal static class CeilingReference
{
    /// <summary>The lowest Z at or above <paramref name="top"/> (less 0.1 mm) of <paramref name="polygons"/> over the open disc (<paramref name="cx"/>, <paramref name="cy"/>, <paramref name="radius"/>); +∞ for none.</summary>
    public static double LowestOver(IEnumerable<Vec3[]> polygons, double cx, double cy, double radius, double top)
    {
        double best = double.PositiveInfinity;
        foreach (Vec3[] v in polygons)
        {
            best = Math.Min(best, LowestOver(v, cx, cy, radius, top - 1e-4));
        }

        return best;
    }

    private static double LowestOver(Vec3[] v, double cx, double cy, double radius, double above)
    {
        double best = double.PositiveInfinity;
        double r2 = radius * radius;

        // Along the edges: points of the outline within the disc.
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            for (int k = 0; k <= 400; k++)
            {
                double s = k / 400.0;
                double x = v[j].X + ((v[i].X - v[j].X) * s), y = v[j].Y + ((v[i].Y - v[j].Y) * s), z = v[j].Z + ((v[i].Z - v[j].Z) * s);
                if (((x - cx) * (x - cx)) + ((y - cy) * (y - cy)) < r2 && z >= above)
                {
                    best = Math.Min(best, z);
                }
            }
        }

        // Over the disc, on the polygon's plane where it is not vertical.
        double nx = 0, ny = 0, nz = 0;
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            nx += (v[j].Y - v[i].Y) * (v[j].Z + v[i].Z);
            ny += (v[j].Z - v[i].Z) * (v[j].X + v[i].X);
            nz += (v[j].X - v[i].X) * (v[j].Y + v[i].Y);
        }

        double length = Math.Sqrt((nx * nx) + (ny * ny) + (nz * nz));
        if (length == 0 || Math.Abs(nz) < 1e-3 * length)
        {
            return best;
        }

        for (int ring = 0; ring <= 48; ring++)
        {
            double rr = radius * ring / 48.0 * 0.999999;
            int count = ring == 0 ? 1 : 192;
            for (int a = 0; a < count; a++)
            {
                double angle = 2 * Math.PI * a / count;
                double x = cx + (rr * Math.Cos(angle)), y = cy + (rr * Math.Sin(angle));
                if (!Inside(v, x, y))
                {
                    continue;
                }

                double z = v[0].Z - (((nx * (x - v[0].X)) + (ny * (y - v[0].Y))) / nz);
                if (z >= above)
                {
                    best = Math.Min(best, z);
                }
            }
        }

        return best;
    }

    private static bool Inside(Vec3[] v, double x, double y)
    {
        bool inside = false;
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            if ((v[i].Y > y) != (v[j].Y > y) && x < v[j].X + ((y - v[j].Y) * (v[i].X - v[j].X) / (v[i].Y - v[j].Y)))
            {
                inside = !inside;
            }
        }

        return inside;
    }
}
