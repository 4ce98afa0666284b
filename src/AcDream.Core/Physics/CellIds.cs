using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// Arithmetic on landblock and cell ids (<c>0xXXYYCCCC</c>: landblock X, landblock Y, cell number),
/// so callers need no bit arithmetic of their own.
/// </summary>
/// <remarks>
/// Cell numbers: 0x0001..0x0040 are the 64 outdoor cells (<c>cx·8 + cy + 1</c>, 24 m squares),
/// 0x0100..0xFFFD indoor cells (EnvCells), 0xFFFF the landblock itself (and, as a portal's
/// neighbour, the outdoors), 0xFFFE its object list.
/// </remarks>
public static class CellIds
{
    /// <summary>First indoor cell number; below it a cell number is outdoor.</summary>
    public const uint FirstIndoor = 0x0100;

    /// <summary>Last indoor cell number (0xFFFE is the object list, 0xFFFF the landblock).</summary>
    public const uint LastIndoor = 0xFFFD;

    /// <summary>The cell number a portal names when it leads out of a building, onto the terrain: 0xFFFF.</summary>
    public const ushort OutdoorPortalTarget = 0xFFFF;

    /// <summary>
    /// Whether the id names a cell of the world: an outdoor cell (0x0001..0x0040), an indoor one (0x0100..0xFFFD), the
    /// landblock (0xFFFF) or its object list (0xFFFE), of a landblock whose X and Y are in the world (not 0xFF).
    /// </summary>
    internal static bool IsCellOfTheWorld(uint cellId)
    {
        uint low = cellId & 0xFFFF;
        return !((low > PhysicsConstants.CellsPerSide * PhysicsConstants.CellsPerSide && low < FirstIndoor) || low > LastIndoor)
            && IsInWorld(LandblockX(cellId), LandblockY(cellId));
    }

    /// <summary>Landblock X index (0..0xFE in the world) of any id.</summary>
    public static int LandblockX(uint id) => (int)(id >> 24);

    /// <summary>Landblock Y index (0..0xFE in the world) of any id.</summary>
    public static int LandblockY(uint id) => (int)((id >> 16) & 0xFF);

    /// <summary>The cell number of an id: its low 16 bits (<c>CCCC</c>).</summary>
    public static ushort CellNumber(uint id) => (ushort)(id & 0xFFFF);

    /// <summary>The landblock of any id, as the dat names it: <c>0xXXYYFFFF</c>.</summary>
    public static uint LandblockOf(uint id) => (id & 0xFFFF0000u) | 0xFFFFu;

    /// <summary>The landblock (<c>0xXXYYFFFF</c>) with indices X and Y.</summary>
    public static uint Landblock(int landblockX, int landblockY) => Prefix(landblockX, landblockY) | 0xFFFFu;

    /// <summary>Whether the id names an indoor cell (cell number 0x0100..0xFFFD).</summary>
    public static bool IsIndoor(uint id) => (id & 0xFFFF) is >= FirstIndoor and <= LastIndoor;

    /// <summary>Whether the id names an outdoor cell (cell number 0x0001..0x0040).</summary>
    public static bool IsOutdoor(uint id) => (id & 0xFFFF) is >= 1 and <= PhysicsConstants.CellsPerSide * PhysicsConstants.CellsPerSide;

    /// <summary>
    /// The outdoor cell number (0x0001..0x0040, <c>cx·8 + cy + 1</c>) at landblock-local (x, y) metres.
    /// A point on a cell edge belongs to the cell east or north of it; positions outside 0..192 clamp,
    /// so x = 192 is in the last column. The one formula the engine, its per-cell buckets,
    /// <see cref="TerrainSurface.ComputeOutdoorCellId"/> and the terrain's triangles use.
    /// </summary>
    /// <exception cref="ArgumentException">A coordinate is NaN or infinite.</exception>
    public static uint OutdoorCellNumber(float localX, float localY)
    {
        if (!float.IsFinite(localX) || !float.IsFinite(localY))
        {
            throw new ArgumentException($"landblock-local position ({localX}, {localY}) must be finite.", float.IsFinite(localX) ? nameof(localY) : nameof(localX));
        }

        return OutdoorCellNumberUnchecked(localX, localY);
    }

    /// <summary><see cref="OutdoorCellNumber"/> for coordinates known to be finite.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static uint OutdoorCellNumberUnchecked(float localX, float localY) =>
        (uint)((OutdoorColumn(localX) * PhysicsConstants.CellsPerSide) + OutdoorColumn(localY) + 1);

    /// <summary>A landblock-local coordinate in cell widths, clamped to the landblock: 0..8.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static double InCells(float coordinate) =>
        Math.Clamp(coordinate, 0f, PhysicsConstants.LandblockSize) * (1.0 / PhysicsConstants.CellSize);

    /// <summary>The outdoor cell column (or row) 0..7 of a finite landblock-local coordinate, clamped.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static int OutdoorColumn(float coordinate) => Math.Min((int)InCells(coordinate), PhysicsConstants.CellsPerSide - 1);

    internal static uint Prefix(uint id) => id & 0xFFFF0000u;

    internal static uint Prefix(int landblockX, int landblockY) => ((uint)landblockX << 24) | ((uint)landblockY << 16);

    /// <summary>Dense index of a landblock for lookup tables: X·256 + Y.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static int LandblockIndex(int landblockX, int landblockY) => (landblockX << 8) | landblockY;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool IsInWorld(int landblockX, int landblockY) =>
        (uint)landblockX <= PhysicsConstants.MaxLandblockIndex && (uint)landblockY <= PhysicsConstants.MaxLandblockIndex;

    /// <summary>
    /// Checks a landblock id: X and Y within the world, low 16 bits 0xFFFF (the dat id) or 0x0000.
    /// </summary>
    internal static void ValidateLandblockId(uint landblockId, string paramName)
    {
        uint low = landblockId & 0xFFFF;
        if (low != 0xFFFF && low != 0)
        {
            throw new ArgumentException(
                $"landblock id 0x{landblockId:X8}: the low 16 bits must be 0xFFFF (the landblock's dat id) or 0x0000, not 0x{low:X4}.",
                paramName);
        }

        if (!IsInWorld(LandblockX(landblockId), LandblockY(landblockId)))
        {
            throw new ArgumentException(
                $"landblock id 0x{landblockId:X8}: X and Y must be within 0x00..0x{PhysicsConstants.MaxLandblockIndex:X2}.",
                paramName);
        }
    }
}
