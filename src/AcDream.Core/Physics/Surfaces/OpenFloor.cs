using System.Numerics;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// Where a cell's floor is open, built with the cell (and again with the objects placed in it): squares of <see cref="PhysicsConstants.OpenFloorSquare"/>
/// over the floor's bounds, each with the height span (lowest bottom to highest top) of the walls whose bounds meet it
/// (the cell's own and its objects'), and whether a portal's bounds meet it. A body move whose sweep box's squares hold
/// no wall reaching into its height band, and whose wall-set box's squares hold no portal, meets no wall: its planner
/// lists only its own cell (no portal leads it on) and sweeps nothing there. A box reaching past the floor's bounds is
/// never open. Landblock-local metres; queries allocate nothing.
/// </summary>
internal sealed class OpenFloor
{
    private readonly Vector2 _min;
    private readonly int _columns;
    private readonly int _rows;
    private readonly Square[] _squares;

    private OpenFloor(Vector2 min, int columns, int rows)
    {
        (_min, _columns, _rows) = (min, columns, rows);
        _squares = new Square[columns * rows];
        Array.Fill(_squares, new Square { Bottom = float.PositiveInfinity, Top = float.NegativeInfinity });
    }

    /// <summary>The open floor of <paramref name="cell"/> (with the objects standing in it); null when it has no floor.</summary>
    public static OpenFloor? Build(CellSurface cell)
    {
        if (!(cell.FloorMin.X <= cell.FloorMax.X && cell.FloorMin.Y <= cell.FloorMax.Y))
        {
            return null;
        }

        Vector2 extent = cell.FloorMax - cell.FloorMin;
        int columns = Math.Clamp((int)MathF.Ceiling(extent.X / PhysicsConstants.OpenFloorSquare), 1, PhysicsConstants.FloorGridMaxSide);
        int rows = Math.Clamp((int)MathF.Ceiling(extent.Y / PhysicsConstants.OpenFloorSquare), 1, PhysicsConstants.FloorGridMaxSide);
        var open = new OpenFloor(cell.FloorMin, columns, rows);
        WallPolygon[] own = cell.Walls.Polygons;
        for (int i = 0; i < own.Length; i++)
        {
            open.Mark(own[i].Min, own[i].Max, own[i].ZMin, own[i].ZMax, i < 64 ? 1UL << i : 0UL);
        }

        foreach (ObjectSurface o in cell.Objects)
        {
            foreach (WallPolygon w in o.Walls.Polygons)
            {
                open.Mark(w.Min, w.Max, w.ZMin, w.ZMax, 0UL);
            }
        }

        foreach (PortalShape portal in cell.PortalShapes)
        {
            open.Mark(portal.BoundsMin, portal.BoundsMax, float.NegativeInfinity, float.PositiveInfinity, 0UL, portal: true);
        }

        return open;
    }

    /// <summary>
    /// Whether no wall's bounds meet <paramref name="lo"/>–<paramref name="hi"/> (seen from above) reaching into the band
    /// <paramref name="zLow"/>–<paramref name="zHigh"/> (open at both ends), and no portal's bounds meet
    /// <paramref name="portalLo"/>–<paramref name="portalHi"/>. False when either box reaches past the floor's squares.
    /// </summary>
    public bool IsOpen(Vector2 lo, Vector2 hi, float zLow, float zHigh, Vector2 portalLo, Vector2 portalHi)
    {
        if (!Within(lo, hi) || !Within(portalLo, portalHi))
        {
            return false;
        }

        (int c0, int c1, int r0, int r1) = Squares(portalLo, portalHi);
        for (int c = c0; c <= c1; c++)
        {
            for (int r = r0; r <= r1; r++)
            {
                if (_squares[(c * _rows) + r].Portal)
                {
                    return false;
                }
            }
        }

        (c0, c1, r0, r1) = Squares(lo, hi);
        for (int c = c0; c <= c1; c++)
        {
            for (int r = r0; r <= r1; r++)
            {
                ref readonly Square square = ref _squares[(c * _rows) + r];
                if (square.Top > zLow && square.Bottom < zHigh)
                {
                    return false;
                }
            }
        }

        return true;
    }

    /// <summary>
    /// The cell's own walls whose bounds may meet <paramref name="lo"/>–<paramref name="hi"/>: bit i for polygon i of its
    /// <see cref="CellSurface.Walls"/> (the first 64; a cell with more is read whole). A box reaching past the floor's
    /// squares reads the border squares, which hold every wall beyond them.
    /// </summary>
    public ulong WallsNear(Vector2 lo, Vector2 hi)
    {
        ulong near = 0;
        (int c0, int c1, int r0, int r1) = Squares(lo, hi);
        for (int c = c0; c <= c1; c++)
        {
            for (int r = r0; r <= r1; r++)
            {
                near |= _squares[(c * _rows) + r].Walls;
            }
        }

        return near;
    }

    /// <summary>Notes a wall (<paramref name="bit"/>: its own wall's, else 0) or a portal with bounds <paramref name="min"/>–<paramref name="max"/> in every square they meet; bounds beyond the floor's squares are noted in the border squares.</summary>
    private void Mark(Vector2 min, Vector2 max, float zMin, float zMax, ulong bit, bool portal = false)
    {
        (int c0, int c1, int r0, int r1) = Squares(min, max);
        for (int c = c0; c <= c1; c++)
        {
            for (int r = r0; r <= r1; r++)
            {
                ref Square square = ref _squares[(c * _rows) + r];
                (square.Bottom, square.Top) = (MathF.Min(square.Bottom, zMin), MathF.Max(square.Top, zMax));
                square.Portal |= portal;
                square.Walls |= bit;
            }
        }
    }

    /// <summary>Whether a box lies within the floor's squares (the border squares hold what lies beyond them).</summary>
    private bool Within(Vector2 lo, Vector2 hi) =>
        lo.X >= _min.X && lo.Y >= _min.Y
        && hi.X <= _min.X + (_columns * PhysicsConstants.OpenFloorSquare) && hi.Y <= _min.Y + (_rows * PhysicsConstants.OpenFloorSquare);

    /// <summary>The squares a box meets, clamped to the grid.</summary>
    private (int C0, int C1, int R0, int R1) Squares(Vector2 lo, Vector2 hi) =>
        (Index(lo.X - _min.X, _columns), Index(hi.X - _min.X, _columns), Index(lo.Y - _min.Y, _rows), Index(hi.Y - _min.Y, _rows));

    private static int Index(float offset, int count) =>
        Math.Clamp((int)MathF.Floor(offset / PhysicsConstants.OpenFloorSquare), 0, count - 1);

    /// <summary>One square: the height span of the walls meeting it, which of the cell's own walls do, and whether a portal does.</summary>
    private struct Square
    {
        public float Bottom;
        public float Top;
        public ulong Walls;
        public bool Portal;
    }
}
