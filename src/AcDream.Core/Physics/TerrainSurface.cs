using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// Outdoor ground of one landblock: heights on a 9 × 9 vertex grid, 24 m apart, in landblock-local
/// metres (x east and y north, both 0..192 m; z up).
/// </summary>
/// <remarks>
/// Two surfaces are available, chosen by the constructor:
/// <list type="bullet">
/// <item><see cref="TerrainSurface(byte[], float[])"/>: the spec's bilinear patch per 24 m cell.
/// It is not the ground the game or the renderer draws: on hilly land it floats above or sinks
/// into the drawn hill by up to <c>|h_SW + h_NE − h_SE − h_NW| / 4</c> at a cell centre.</item>
/// <item><see cref="TerrainSurface(byte[], float[], uint)"/>: the game's own surface, two flat
/// triangles per cell, split along the diagonal the game picks from the global cell coordinates.
/// Use this one for a player: it is the ground the renderer draws.</item>
/// </list>
/// Both surfaces are continuous across cell edges and, given the same heights on the shared edge,
/// across landblock seams. Instances are immutable and safe to share between threads.
/// </remarks>
public sealed class TerrainSurface
{
    private const int Side = PhysicsConstants.VerticesPerSide;

    /// <summary>Vertex heights in metres, x-major: vertex (x, y) at [x * 9 + y].</summary>
    private readonly float[] _z;

    /// <summary>Bit (cx * 8 + cy) set when cell (cx, cy) is split SW–NE; clear when SE–NW. Unused when bilinear.</summary>
    private readonly ulong _swToNeCells;

    /// <summary>
    /// Bilinear Z-interpolated terrain constructor, literal to the spec. See the remarks of
    /// <see cref="TerrainSurface"/> for when to use it.
    /// </summary>
    /// <param name="heights"><c>LandBlock.Height</c>: 81 height-table indices, x-major (<c>heights[x * 9 + y]</c>).</param>
    /// <param name="heightTable">The region's <c>LandHeightTable</c>: 256 finite heights in metres (not necessarily linear).</param>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="ArgumentException">An array has the wrong length, or a height is not finite.</exception>
    public TerrainSurface(byte[] heights, float[] heightTable)
        : this(heights, heightTable, null)
    {
    }

    /// <summary>
    /// The game's terrain for landblock <paramref name="landblockId"/>: each 24 m cell is two flat
    /// triangles, split SW–NE or SE–NW by the game's rule on the global cell coordinates. This is the
    /// ground the renderer draws; use it for anything that walks.
    /// </summary>
    /// <param name="heights"><c>LandBlock.Height</c>: 81 height-table indices, x-major (<c>heights[x * 9 + y]</c>).</param>
    /// <param name="heightTable">The region's <c>LandHeightTable</c>: 256 finite heights in metres (not necessarily linear).</param>
    /// <param name="landblockId">The landblock's id, <c>0xXXYYFFFF</c> (or <c>0xXXYY0000</c>); X and Y pick the diagonals.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">An array has the wrong length, a height is not finite, or the id is not a landblock id.</exception>
    public TerrainSurface(byte[] heights, float[] heightTable, uint landblockId)
        : this(heights, heightTable, (uint?)landblockId)
    {
    }

    private TerrainSurface(byte[] heights, float[] heightTable, uint? landblockId)
    {
        ArgumentNullException.ThrowIfNull(heights);
        ArgumentNullException.ThrowIfNull(heightTable);
        string who = landblockId is uint id ? $"landblock 0x{id:X8}" : "terrain";
        if (heights.Length != Side * Side)
        {
            throw new ArgumentException($"{who}: heights must have {Side * Side} entries (9 × 9 vertices), not {heights.Length}.", nameof(heights));
        }

        if (heightTable.Length != 256)
        {
            throw new ArgumentException($"{who}: heightTable must have 256 entries, not {heightTable.Length}.", nameof(heightTable));
        }

        for (int i = 0; i < heightTable.Length; i++)
        {
            if (!float.IsFinite(heightTable[i]))
            {
                throw new ArgumentException($"{who}: heightTable[{i}] is {heightTable[i]}; heights must be finite.", nameof(heightTable));
            }
        }

        _z = new float[Side * Side];
        for (int i = 0; i < _z.Length; i++)
        {
            _z[i] = heightTable[heights[i]];
        }

        if (landblockId is uint lb)
        {
            CellIds.ValidateLandblockId(lb, nameof(landblockId));
            LandblockId = CellIds.Prefix(lb) | 0xFFFF;
            _swToNeCells = SplitMask(CellIds.LandblockX(lb), CellIds.LandblockY(lb));
        }
    }

    /// <summary>
    /// The landblock id (<c>0xXXYYFFFF</c>) this surface was built for with the game's triangles;
    /// null for the bilinear surface, which belongs to no particular landblock.
    /// </summary>
    public uint? LandblockId { get; }

    /// <summary>
    /// Terrain Z at (localX, localY) in landblock-local coordinates (0..192 range): the game's
    /// triangle under the point (three-argument constructor), or the spec's bilinear patch (the
    /// two-argument one). Clamps to the landblock bounds if the position is outside.
    /// </summary>
    /// <remarks>
    /// Metres in, metres out. With the game's triangles (the three-argument constructor) the Z is
    /// that of the triangle containing the point; a point on the diagonal or a cell edge gets the
    /// same Z from both sides. Coordinates outside 0..192 clamp to the nearest edge.
    /// </remarks>
    /// <exception cref="ArgumentException">A coordinate is NaN or infinite.</exception>
    public float SampleZ(float localX, float localY)
    {
        if (!float.IsFinite(localX) || !float.IsFinite(localY))
        {
            ThrowNotFinite(localX, localY);
        }

        Locate(localX, localY, out int cx, out int cy, out double u, out double v);
        return InterpolateCell(cx, cy, u, v);
    }

    /// <summary>
    /// Compute the outdoor cell ID for the given local position.
    /// Outdoor cells are a flat 8×8 grid of 24×24 unit cells
    /// numbered 0x0001..0x0040. The cell at (0,0) is 0x0001.
    /// </summary>
    /// <remarks>
    /// Returns the low 16 bits only (<c>cx * 8 + cy + 1</c>, x-major); the engine adds the landblock
    /// prefix. A point on a cell edge belongs to the cell east or north of it; positions outside
    /// 0..192 clamp, so x = 192 is in the last column.
    /// </remarks>
    /// <exception cref="ArgumentException">A coordinate is NaN or infinite.</exception>
    public uint ComputeOutdoorCellId(float localX, float localY)
    {
        if (!float.IsFinite(localX) || !float.IsFinite(localY))
        {
            ThrowNotFinite(localX, localY);
        }

        return CellIds.OutdoorCellNumberUnchecked(localX, localY);
    }

    /// <summary>
    /// Whether the game splits global cell (gx, gy) along the SW–NE diagonal (top bit of the
    /// game's split value set); otherwise it is split SE–NW.
    /// </summary>
    internal static bool IsSplitSwToNe(uint globalCellX, uint globalCellY) => (SplitValue(globalCellX, globalCellY) & 0x8000_0000u) != 0;

    /// <summary>The game's diagonal hash of global cell (gx, gy), with unsigned 32-bit wrap-around.</summary>
    internal static uint SplitValue(uint gx, uint gy) =>
        unchecked((gx * gy * 0x0CCAC033u) - (gx * 0x421BE3BDu) + (gy * 0x6C1AC587u) - 0x519B8F25u);

    /// <summary>Z at a point already known to be finite; the engine's hot path.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal float SampleZUnchecked(float localX, float localY)
    {
        Locate(localX, localY, out int cx, out int cy, out double u, out double v);
        return InterpolateCell(cx, cy, u, v);
    }

    /// <summary>
    /// Z of the unit surface normal at a point already known to be finite: of the triangle under it
    /// (game triangles) or of the bilinear patch's tangent plane. 1 on flat ground.
    /// </summary>
    internal float NormalZUnchecked(float localX, float localY) => NormalUnchecked(localX, localY).Z;

    /// <summary>
    /// The unit surface normal (pointing up) at a point already known to be finite: of the triangle
    /// under it (game triangles) or of the bilinear patch's tangent plane. (0, 0, 1) on flat ground.
    /// </summary>
    internal Vector3 NormalUnchecked(float localX, float localY)
    {
        Locate(localX, localY, out int cx, out int cy, out double u, out double v);
        int sw = (cx * Side) + cy;
        double hSW = _z[sw], hNW = _z[sw + 1], hSE = _z[sw + Side], hNE = _z[sw + Side + 1];
        double du, dv; // metres of rise per cell width along x and y
        if (LandblockId is null)
        {
            du = ((1 - v) * (hSE - hSW)) + (v * (hNE - hNW));
            dv = ((1 - u) * (hNW - hSW)) + (u * (hNE - hSE));
        }
        else if ((_swToNeCells & (1ul << ((cx * PhysicsConstants.CellsPerSide) + cy))) != 0)
        {
            (du, dv) = u >= v ? (hSE - hSW, hNE - hSE) : (hNE - hNW, hNW - hSW);
        }
        else
        {
            (du, dv) = u + v <= 1.0 ? (hSE - hSW, hNW - hSW) : (hNE - hNW, hNE - hSE);
        }

        double gx = du / PhysicsConstants.CellSize, gy = dv / PhysicsConstants.CellSize;
        double n = 1.0 / Math.Sqrt(1.0 + (gx * gx) + (gy * gy));
        return new Vector3((float)(-gx * n), (float)(-gy * n), (float)n);
    }

    /// <summary>The corner heights, metres, of terrain cell (cx, cy) (each index 0..7).</summary>
    internal void Corners(int cx, int cy, out double sw, out double nw, out double se, out double ne)
    {
        int i = (cx * Side) + cy;
        (sw, nw, se, ne) = (_z[i], _z[i + 1], _z[i + Side], _z[i + Side + 1]);
    }

    /// <summary>With the game's triangles: whether terrain cell (cx, cy) is split SW–NE (else SE–NW).</summary>
    internal bool IsSplitSwToNe(int cx, int cy) => (_swToNeCells & (1ul << ((cx * PhysicsConstants.CellsPerSide) + cy))) != 0;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Locate(float x, float y, out int cx, out int cy, out double u, out double v)
    {
        double fx = CellIds.InCells(x), fy = CellIds.InCells(y);
        cx = Math.Min((int)fx, PhysicsConstants.CellsPerSide - 1); // = CellIds.OutdoorColumn
        cy = Math.Min((int)fy, PhysicsConstants.CellsPerSide - 1);
        u = fx - cx;
        v = fy - cy;
    }

    /// <summary>
    /// Z inside cell (cx, cy) at fractions (u, v) of it. Computed in double and rounded once, so a
    /// point on an edge shared by two cells or two landblocks gets the same float from both sides
    /// (the two formulas agree to ~1e-13 m there; float rounding of each would not).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private float InterpolateCell(int cx, int cy, double u, double v)
    {
        int sw = (cx * Side) + cy;
        double hSW = _z[sw];
        double hNW = _z[sw + 1];
        double hSE = _z[sw + Side];
        double hNE = _z[sw + Side + 1];

        if (LandblockId is null)
        {
            double south = hSW + (u * (hSE - hSW));
            double north = hNW + (u * (hNE - hNW));
            return (float)(south + (v * (north - south)));
        }

        if ((_swToNeCells & (1ul << ((cx * PhysicsConstants.CellsPerSide) + cy))) != 0)
        {
            // Diagonal SW–NE: triangle (SW, SE, NE) below it (u ≥ v), (SW, NE, NW) above it.
            return (float)(u >= v
                ? hSW + (u * (hSE - hSW)) + (v * (hNE - hSE))
                : hSW + (v * (hNW - hSW)) + (u * (hNE - hNW)));
        }

        // Diagonal SE–NW: triangle (SW, SE, NW) below it (u + v ≤ 1), (NE, NW, SE) above it.
        return (float)(u + v <= 1.0
            ? hSW + (u * (hSE - hSW)) + (v * (hNW - hSW))
            : hNE + ((1.0 - u) * (hNW - hNE)) + ((1.0 - v) * (hSE - hNE)));
    }

    private static ulong SplitMask(int landblockX, int landblockY)
    {
        // One pass per bit of the mask (bit cx * 8 + cy): the loop ends when the bit leaves the word.
        ulong mask = 0;
        int cell = 0;
        for (ulong bit = 1; bit != 0; bit <<= 1, cell++)
        {
            uint gx = (uint)((landblockX * PhysicsConstants.CellsPerSide) + (cell / PhysicsConstants.CellsPerSide));
            uint gy = (uint)((landblockY * PhysicsConstants.CellsPerSide) + (cell % PhysicsConstants.CellsPerSide));
            if (IsSplitSwToNe(gx, gy))
            {
                mask |= bit;
            }
        }

        return mask;
    }

    private static void ThrowNotFinite(float x, float y) =>
        throw new ArgumentException($"terrain position ({x}, {y}) must be finite.", float.IsFinite(x) ? "localY" : "localX");
}
