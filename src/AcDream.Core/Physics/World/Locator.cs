using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.World;

/// <summary>Where a mover is: its landblock's entry and indices, its landblock-local XY, and its cell's index (−1 outdoors).</summary>
internal readonly struct Place(LandblockEntry entry, int x, int y, Vector2 local, int cellIndex)
{
    public LandblockEntry Entry { get; } = entry;

    public int X { get; } = x;

    public int Y { get; } = y;

    /// <summary>Landblock-local XY, metres, as the world frame represents it (see <see cref="WorldFrame.Representable"/>).</summary>
    public Vector2 Local { get; } = local;

    /// <summary>The indoor cell's index in <see cref="LandblockEntry.Cells"/>; −1 outdoors.</summary>
    public int CellIndex { get; } = cellIndex;
}

/// <summary>
/// The one way a position and cell id become a <see cref="Place"/>: an indoor cell in its own
/// landblock (the position made landblock-local there); an outdoor mover in the landblock its id names
/// when within <see cref="PhysicsConstants.SeamSlack"/> of it, else the one under it. One policy for an
/// indoor cell its loaded landblock does not have: a caller's error (<see cref="ArgumentException"/>),
/// for <c>Resolve</c> and every query alike.
/// </summary>
internal static class Locator
{
    /// <summary>False when the landblock is not loaded; throws when it is and has no such indoor cell.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool TryFind(WorldFrame frame, ref Neighbourhood lands, Vector3 position, uint cellId, out Place place, string paramName = "currentCellId")
    {
        int x, y, index = -1;
        Vector2 local;
        if (CellIds.IsIndoor(cellId))
        {
            (x, y) = (CellIds.LandblockX(cellId), CellIds.LandblockY(cellId));
            local = frame.Representable(x, y, new Vector2(position.X, position.Y) - frame.Origin(x, y));
        }
        else
        {
            frame.Locate(position, cellId, out x, out y, out local);
        }

        if (lands.Get(x, y) is not LandblockEntry entry)
        {
            place = default;
            return false;
        }

        if (CellIds.IsIndoor(cellId) && !entry.TryGetCellIndex(cellId, out index))
        {
            ThrowNotRegistered(cellId, paramName);
        }

        place = new Place(entry, x, y, local, index);
        return true;
    }

    /// <summary>The error of an indoor cell its loaded landblock does not have; out of line, so a caller's frame carries no string builder.</summary>
    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static void ThrowNotRegistered(uint cellId, string paramName) =>
        throw new ArgumentException($"cell 0x{cellId:X8} is not registered in its landblock 0x{CellIds.LandblockOf(cellId):X8}.", paramName);
}
