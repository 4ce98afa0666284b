using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.World;

/// <summary>
/// How far the outdoor things of a landblock's neighbours (their objects and the walls of their
/// buildings, <see cref="LandblockEntry.OutdoorMin"/>–<see cref="LandblockEntry.OutdoorMax"/>) may reach into
/// it past each of its four sides, in whole metres with a metre to spare: a box of the landblock's frame
/// that keeps inside these margins, and inside the landblock, meets nothing of a neighbour. Kept per
/// landblock by <see cref="LandblockRegistry"/>, which only ever raises it (a hint, never too small).
/// </summary>
internal readonly struct SeamReach
{
    private readonly uint _packed; // west, east, south, north: one byte each

    private SeamReach(uint packed) => _packed = packed;

    /// <summary>As packed by <see cref="Packed"/>.</summary>
    public static SeamReach FromPacked(uint packed) => new(packed);

    /// <summary>The value as one word (west, east, south, north: a byte each).</summary>
    public uint Packed => _packed;

    /// <summary>Metres past the west side (x = 0) a neighbour's things may reach in.</summary>
    public float West => _packed & 0xFF;

    /// <summary>Metres past the east side (x = 192) a neighbour's things may reach in.</summary>
    public float East => (_packed >> 8) & 0xFF;

    /// <summary>Metres past the south side (y = 0) a neighbour's things may reach in.</summary>
    public float South => (_packed >> 16) & 0xFF;

    /// <summary>Metres past the north side (y = 192) a neighbour's things may reach in.</summary>
    public float North => _packed >> 24;

    /// <summary>
    /// Whether the box <paramref name="lo"/>–<paramref name="hi"/> (landblock-local metres) comes within a
    /// neighbour's reach, or past a seam: only then can a neighbour's things meet it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Meets(Vector2 lo, Vector2 hi)
    {
        const float size = PhysicsConstants.LandblockSize;
        return lo.X < West || hi.X > size - East || lo.Y < South || hi.Y > size - North;
    }

    /// <summary>Per side, the larger of the two.</summary>
    /// <summary>
    /// The most any neighbour's reach can be, metres past a seam: <see cref="PhysicsConstants.MaxSeamReach"/> and the 2 m
    /// of <see cref="Into"/>'s rounding.
    /// </summary>
    public const float Farthest = PhysicsConstants.MaxSeamReach + 2f;

    /// <summary>
    /// Whether the box <paramref name="lo"/>–<paramref name="hi"/> comes within <see cref="Farthest"/> of a seam: if not,
    /// no reach <see cref="Meets"/> it, so a move in the middle of a landblock reads none.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool NearASeam(Vector2 lo, Vector2 hi)
    {
        const float size = PhysicsConstants.LandblockSize;
        return lo.X < Farthest || hi.X > size - Farthest || lo.Y < Farthest || hi.Y > size - Farthest;
    }

    public static SeamReach Max(SeamReach a, SeamReach b)
    {
        uint packed = 0;
        for (int shift = 0; shift < 32; shift += 8)
        {
            packed |= Math.Max((a._packed >> shift) & 0xFF, (b._packed >> shift) & 0xFF) << shift;
        }

        return new(packed);
    }

    /// <summary>
    /// How far <paramref name="entry"/>'s outdoor things reach into its neighbour at (<paramref name="dx"/>,
    /// <paramref name="dy"/>) (each −1, 0 or 1): nothing when they do not reach that neighbour's square.
    /// </summary>
    public static SeamReach Into(LandblockEntry entry, int dx, int dy)
    {
        const float size = PhysicsConstants.LandblockSize;
        Vector2 min = entry.OutdoorMin, max = entry.OutdoorMax;
        if (min.X > max.X)
        {
            return default; // nothing outdoors
        }

        // Past the seam by r metres: floor(r) + 2 covers r with a metre to spare for the rounding of the frames.
        uint west = dx > 0 ? Past(max.X - size) : 0, east = dx < 0 ? Past(-min.X) : 0;
        uint south = dy > 0 ? Past(max.Y - size) : 0, north = dy < 0 ? Past(-min.Y) : 0;
        bool reaches = (dx == 0 || (west | east) != 0) && (dy == 0 || (south | north) != 0);
        return reaches ? new(west | (east << 8) | (south << 16) | (north << 24)) : default;

        // The byte for a reach r past a seam (at most MaxSeamReach, which the engine checks): 0 when it does not reach it.
        static uint Past(float r) => r >= 0f ? (uint)MathF.Floor(Math.Min(r, PhysicsConstants.MaxSeamReach)) + 2u : 0u;
    }
}
