using AcDream.Core.Physics.Surfaces;
namespace AcDream.Core.Physics.Casting;

// SweptSphere against the terrain: a cell's bilinear patch, swept in closed form.
internal partial struct SweptSphere
{
    /// <summary>
    /// The ray (radius 0) or the lowest point (radius R) of the sphere against the bilinear patch of one terrain cell
    /// (south-west corner at <paramref name="x0"/>, <paramref name="y0"/> relative to the start, side
    /// <paramref name="size"/> metres; corner <paramref name="heights"/> relative to the start), met from above, as
    /// terrain cell <paramref name="id"/>.
    /// </summary>
    public void BilinearCell(double x0, double y0, double size, in CornerHeights heights, uint id)
    {
        // Along the ray: u = (tDx − x0)/size, v = (tDy − y0)/size; the lowest point's Z − h(u, v) is a quadratic in t.
        double u0 = -x0 / size, du = Move.X / size, v0 = -y0 / size, dv = Move.Y / size;
        double hSW = heights.SW, hSE = heights.SE, hNW = heights.NW, hNE = heights.NE;
        double a = hSW, b = hSE - hSW, c = hNW - hSW, d = hNE - hNW - hSE + hSW; // h = a + b·u + c·v + d·u·v
        double k0 = -Radius - (a + (b * u0) + (c * v0) + (d * u0 * v0));
        double k1 = Move.Z - ((b * du) + (c * dv) + (d * ((u0 * dv) + (v0 * du))));
        double k2 = -(d * du * dv);

        // Earliest t in the cell's span of the ray where k0 + k1 t + k2 t² falls to 0 from above; below the patch where the
        // ray enters the cell, met at once moving down into it, free of it moving up.
        (double tIn, double tOut) = Span(u0, du, v0, dv);
        if (!(tIn <= tOut))
        {
            return;
        }

        double gapIn = k0 + (k1 * tIn) + (k2 * tIn * tIn), slopeIn = k1 + (2 * k2 * tIn);
        if (gapIn < 0 || (gapIn == 0 && slopeIn < 0))
        {
            if (slopeIn < 0 && MayKeep(tIn))
            {
                Keep(tIn, PatchNormal(u0 + (du * tIn), v0 + (dv * tIn), b, c, d, size), new ShapeName(SurfaceKind.Terrain, id));
            }

            return;
        }

        double best = double.PositiveInfinity;
        if (Math.Abs(k2) < 1e-15)
        {
            if (k1 < 0)
            {
                best = -k0 / k1;
            }
        }
        else
        {
            double disc = (k1 * k1) - (4 * k2 * k0);
            if (disc >= 0)
            {
                double sq = Math.Sqrt(disc);
                double q = -0.5 * (k1 + (k1 >= 0 ? sq : -sq));
                double r1 = q / k2, r2 = q != 0 ? k0 / q : double.PositiveInfinity;
                foreach (double r in (ReadOnlySpan<double>)[r1, r2])
                {
                    if (r >= tIn && r < best && k1 + (2 * k2 * r) < 0)
                    {
                        best = r; // falling through the patch there (a root where the ray rises off it is not a contact)
                    }
                }
            }
        }

        if (best < tIn || best > tOut || !MayKeep(best))
        {
            return;
        }

        Keep(best, PatchNormal(u0 + (du * best), v0 + (dv * best), b, c, d, size), new ShapeName(SurfaceKind.Terrain, id));
    }

    /// <summary>The bilinear patch's unit normal (up) at (u, v), for h = a + b·u + c·v + d·u·v over a cell of side <paramref name="size"/>.</summary>
    private static D3 PatchNormal(double u, double v, double b, double c, double d, double size)
    {
        double gx = (b + (d * v)) / size, gy = (c + (d * u)) / size;
        double n = 1.0 / Math.Sqrt(1.0 + (gx * gx) + (gy * gy));
        return new D3(-gx * n, -gy * n, n);
    }

    /// <summary>The fractions of the ray within the unit square u, v ∈ 0..1 (empty: in &gt; out).</summary>
    private static (double In, double Out) Span(double u0, double du, double v0, double dv)
    {
        double tIn = 0, tOut = 1;
        Clip(u0, du, ref tIn, ref tOut);
        Clip(v0, dv, ref tIn, ref tOut);
        return (tIn, tOut);

        static void Clip(double s0, double ds, ref double tIn, ref double tOut)
        {
            if (ds == 0)
            {
                if (s0 < 0 || s0 > 1)
                {
                    (tIn, tOut) = (1, 0);
                }

                return;
            }

            double ta = -s0 / ds, tb = (1 - s0) / ds;
            (tIn, tOut) = (Math.Max(tIn, Math.Min(ta, tb)), Math.Min(tOut, Math.Max(ta, tb)));
        }
    }
}

/// <summary>The heights of a terrain cell's four corners (south-west, south-east, north-west, north-east), in metres.</summary>
internal readonly record struct CornerHeights(double SW, double SE, double NW, double NE);
