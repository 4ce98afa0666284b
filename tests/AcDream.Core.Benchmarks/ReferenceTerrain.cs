namespace AcDream.Core.Benchmarks;

/// <summary>
/// The game's terrain in double precision, written independently of the engine from the game's
/// rule: two flat triangles per 24 m cell, split SW–NE when the top bit of the split hash of the
/// global cell coordinates is set, else SE–NW. Gives Z and the unit normal's Z.
/// </summary>
internal sealed class ReferenceTerrain
{
    private readonly double[] _z = new double[81];
    private readonly int _landblockX;
    private readonly int _landblockY;

    public ReferenceTerrain(byte[] heights, float[] table, uint landblockId)
    {
        for (int i = 0; i < 81; i++)
        {
            _z[i] = table[heights[i]];
        }

        _landblockX = (int)(landblockId >> 24);
        _landblockY = (int)((landblockId >> 16) & 0xFF);
    }

    /// <summary>Z (metres) and unit normal Z at landblock-local (x, y), clamped to 0..192.</summary>
    public (double Z, double NormalZ) Sample(double x, double y)
    {
        double fx = Math.Clamp(x, 0, 192) / 24, fy = Math.Clamp(y, 0, 192) / 24;
        int cx = Math.Min((int)fx, 7), cy = Math.Min((int)fy, 7);
        double u = fx - cx, v = fy - cy;
        double sw = _z[(cx * 9) + cy], nw = _z[(cx * 9) + cy + 1], se = _z[((cx + 1) * 9) + cy], ne = _z[((cx + 1) * 9) + cy + 1];
        uint gx = (uint)((_landblockX * 8) + cx), gy = (uint)((_landblockY * 8) + cy);
        uint hash = unchecked((gx * gy * 0x0CCAC033u) - (gx * 0x421BE3BDu) + (gy * 0x6C1AC587u) - 0x519B8F25u);
        double z, du, dv; // du, dv: rise per cell width along x and y
        if ((hash & 0x8000_0000u) != 0)
        {
            (du, dv) = u >= v ? (se - sw, ne - se) : (ne - nw, nw - sw);
            z = sw + (u * du) + (v * dv);
        }
        else if (u + v <= 1)
        {
            (du, dv) = (se - sw, nw - sw);
            z = sw + (u * du) + (v * dv);
        }
        else
        {
            (du, dv) = (ne - nw, ne - se);
            z = ne - ((1 - u) * du) - ((1 - v) * dv);
        }

        double gxSlope = du / 24, gySlope = dv / 24;
        return (z, 1 / Math.Sqrt(1 + (gxSlope * gxSlope) + (gySlope * gySlope)));
    }
}
