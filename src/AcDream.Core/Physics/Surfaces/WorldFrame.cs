using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// The engine's world frame: where landblock (X, Y)'s south-west corner lies in world metres, and the
/// conversions between world and landblock-local positions. World = (X − originX)·192 + local, so
/// the global frame has origin (0, 0) and a centred frame the centre landblock's indices.
/// </summary>
/// <remarks>Immutable; safe to share between threads.</remarks>
internal readonly struct WorldFrame(int originX, int originY)
{
    public int OriginX { get; } = originX;

    public int OriginY { get; } = originY;

    /// <summary>World X (or Y) of the south-west corner of landblock index <paramref name="landblock"/>, metres.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Offset(int landblock, int origin) => (landblock - origin) * PhysicsConstants.LandblockSize;

    /// <summary>World XY of the south-west corner of landblock (lbX, lbY), metres.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector2 Origin(int lbX, int lbY) => new(Offset(lbX, OriginX), Offset(lbY, OriginY));

    /// <summary>The world position of landblock-local (local, z) in landblock (lbX, lbY): one rounding.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector3 ToWorld(int lbX, int lbY, Vector2 local, float z) =>
        new(Offset(lbX, OriginX) + local.X, Offset(lbY, OriginY) + local.Y, z);

    /// <summary>
    /// The landblock-local point that survives the round trip to the world frame: the local value of
    /// the world position it is returned as. Every surface is sampled there, so a returned position is
    /// exactly where its answer was computed, and resolving it again finds the same ground. Exact after
    /// one round trip (the subtraction of the landblock's offset from a rounded world value is exact).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector2 Representable(int lbX, int lbY, Vector2 local)
    {
        Vector2 origin = Origin(lbX, lbY);
        return (origin + local) - origin;
    }

    /// <summary>
    /// The landblock an outdoor mover is resolved from, and its landblock-local position: the one its
    /// cell id names when the position is within <see cref="PhysicsConstants.SeamSlack"/> of it (world
    /// rounding far from the origin can put a position a hair past a seam), else the one under it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Locate(Vector3 pos, uint cellId, out int lbX, out int lbY, out Vector2 local)
    {
        if ((cellId & 0xFFFF) != 0)
        {
            lbX = CellIds.LandblockX(cellId);
            lbY = CellIds.LandblockY(cellId);
            local = Representable(lbX, lbY, new Vector2(pos.X, pos.Y) - Origin(lbX, lbY));
            const float slack = PhysicsConstants.SeamSlack;
            if (local.X >= -slack && local.Y >= -slack
                && local.X <= PhysicsConstants.LandblockSize + slack && local.Y <= PhysicsConstants.LandblockSize + slack)
            {
                return;
            }
        }

        lbX = OriginX;
        lbY = OriginY;
        local = new Vector2(pos.X, pos.Y);
        Wrap(ref local.X, ref lbX);
        Wrap(ref local.Y, ref lbY);
        local = Representable(lbX, lbY, local);
    }

    /// <summary>The landblock (<c>0xXXYYFFFF</c>) under a world position; positions off the world clamp to its nearest edge.</summary>
    public uint LandblockAt(Vector3 world)
    {
        int x = Index(world.X, OriginX), y = Index(world.Y, OriginY);
        return CellIds.Landblock(x, y);

        static int Index(float coordinate, int origin) =>
            (int)Math.Clamp(origin + Math.Floor(coordinate / (double)PhysicsConstants.LandblockSize), 0, PhysicsConstants.MaxLandblockIndex);
    }

    /// <summary>
    /// Moves a landblock-local coordinate into 0 ≤ c &lt; 192, stepping the landblock index to match.
    /// Exact: subtracting a multiple of 192 from a float in the adjacent range loses nothing.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Wrap(ref float coordinate, ref int landblock)
    {
        if (!(coordinate >= 0f && coordinate < PhysicsConstants.LandblockSize))
        {
            WrapAcrossSeam(ref coordinate, ref landblock);
        }
    }

    /// <summary><see cref="Wrap"/> for a coordinate outside 0..192: out of line, since most moves stay inside.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void WrapAcrossSeam(ref float coordinate, ref int landblock)
    {
        double steps = Math.Floor(coordinate / (double)PhysicsConstants.LandblockSize);
        steps = Math.Clamp(steps, -2 * PhysicsConstants.WorldSide, 2 * PhysicsConstants.WorldSide); // far off the world; stays off it
        coordinate = (float)(coordinate - (steps * PhysicsConstants.LandblockSize));
        landblock += (int)steps;
        if (coordinate >= PhysicsConstants.LandblockSize)
        {
            coordinate -= PhysicsConstants.LandblockSize; // rounding put it on the far seam
            landblock++;
        }
    }

    /// <summary>
    /// The full id of the outdoor cell at <paramref name="local"/> of landblock (lbX, lbY). A mover held
    /// off the world (a position beyond its edge) gets the nearest edge cell of the world, never a
    /// wrapped-around prefix of another landblock.
    /// </summary>
    public static uint OutdoorCellId(int lbX, int lbY, Vector2 local)
    {
        if (!CellIds.IsInWorld(lbX, lbY))
        {
            ClampToWorld(ref lbX, ref local.X);
            ClampToWorld(ref lbY, ref local.Y);
        }

        return CellIds.Prefix(lbX, lbY) | CellIds.OutdoorCellNumberUnchecked(local.X, local.Y);

        static void ClampToWorld(ref int landblock, ref float coordinate)
        {
            if (landblock < 0)
            {
                (landblock, coordinate) = (0, 0f);
            }
            else if (landblock > PhysicsConstants.MaxLandblockIndex)
            {
                (landblock, coordinate) = (PhysicsConstants.MaxLandblockIndex, PhysicsConstants.LandblockSize);
            }
        }
    }
}
