namespace AcDream.Core.Physics;

/// <summary>Arithmetic on landblock and cell ids (<c>0xXXYYCCCC</c>).</summary>
internal static class CellIds
{
    /// <summary>First indoor cell number; below it a cell number is outdoor.</summary>
    public const uint FirstIndoor = 0x0100;

    /// <summary>Last indoor cell number (0xFFFE is the object list, 0xFFFF the landblock).</summary>
    public const uint LastIndoor = 0xFFFD;

    /// <summary>The cell number a portal uses for the outdoors.</summary>
    public const ushort Outdoors = 0xFFFF;

    public static int LandblockX(uint id) => (int)(id >> 24);

    public static int LandblockY(uint id) => (int)((id >> 16) & 0xFF);

    public static uint Prefix(uint id) => id & 0xFFFF0000u;

    public static uint Prefix(int landblockX, int landblockY) => ((uint)landblockX << 24) | ((uint)landblockY << 16);

    public static bool IsIndoor(uint id) => (id & 0xFFFF) is >= FirstIndoor and <= LastIndoor;

    /// <summary>Dense index of a landblock for lookup tables: X·256 + Y.</summary>
    public static int LandblockIndex(int landblockX, int landblockY) => (landblockX << 8) | landblockY;

    public static bool IsInWorld(int landblockX, int landblockY) =>
        (uint)landblockX <= PhysicsConstants.MaxLandblockIndex && (uint)landblockY <= PhysicsConstants.MaxLandblockIndex;

    /// <summary>
    /// Checks a landblock id: X and Y within the world, low 16 bits 0xFFFF (the dat id) or 0x0000.
    /// </summary>
    public static void ValidateLandblockId(uint landblockId, string paramName)
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
