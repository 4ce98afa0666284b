using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// The cells whose walls one body move meets, gathered once per call: near the move in the mover's
/// cell and the cells its portals lead to (indoors), or over the outdoor squares it covers, in its
/// own landblock and the neighbours across a seam (outdoors). Held on the stack; the cells are
/// referred to by landblock slot and index, with each slot's offset into the move's frame.
/// </summary>
internal ref struct WallSet
{
    /// <summary>Marks an entry that is an outdoor object of its landblock (<see cref="LandblockEntry.OutdoorObjects"/>), not a cell; indices stay below it.</summary>
    public const int ObjectFlag = 0x10000;

    private readonly Span<int> _cells; // slot << 17 | cell index (< 0x10000), or slot << 17 | ObjectFlag | outdoor object index
    private LandblockEntry? _slot0, _slot1, _slot2, _slot3;
    private Vector2 _offset0, _offset1, _offset2, _offset3;
    private int _slots;
    private int _count;

    /// <summary>An empty set over <paramref name="storage"/>, for the move box centred on <paramref name="centre"/> with half-size <paramref name="reach"/>.</summary>
    public WallSet(Span<int> storage, Vector2 centre, float reach)
    {
        _cells = storage;
        BoxMin = centre - new Vector2(reach);
        BoxMax = centre + new Vector2(reach);
    }

    /// <summary>Every point the body can reach this call lies in this box (move's frame): the start ± (move length + radius).</summary>
    public Vector2 BoxMin { get; }

    public Vector2 BoxMax { get; }

    public readonly int Count => _count;

    /// <summary>Adds landblock <paramref name="entry"/>, whose frame is <paramref name="offset"/> from the move's; returns its slot.</summary>
    public int AddLandblock(LandblockEntry entry, Vector2 offset)
    {
        switch (_slots)
        {
            case 0: (_slot0, _offset0) = (entry, offset); break;
            case 1: (_slot1, _offset1) = (entry, offset); break;
            case 2: (_slot2, _offset2) = (entry, offset); break;
            default: (_slot3, _offset3) = (entry, offset); break;
        }

        return _slots++;
    }

    /// <summary>Adds cell <paramref name="cellIndex"/> of slot <paramref name="slot"/> unless it is present; false (nothing added) when the set is full.</summary>
    public bool TryAdd(int slot, int cellIndex)
    {
        int key = (slot << 17) | cellIndex;
        for (int i = 0; i < _count; i++)
        {
            if (_cells[i] == key)
            {
                return true;
            }
        }

        if (_count == _cells.Length)
        {
            return false;
        }

        _cells[_count++] = key;
        return true;
    }

    /// <summary>The cell at <paramref name="i"/> (insertion order) with its landblock slot.</summary>
    public readonly (int Slot, int Cell) At(int i) => (_cells[i] >> 17, _cells[i] & 0x1FFFF);

    /// <summary>Whether the box, moved into a landblock's frame by −<paramref name="offset"/>, overlaps the bounds given.</summary>
    public readonly bool Overlaps(Vector2 min, Vector2 max, Vector2 offset) =>
        min.X <= BoxMax.X - offset.X && max.X >= BoxMin.X - offset.X && min.Y <= BoxMax.Y - offset.Y && max.Y >= BoxMin.Y - offset.Y;

    /// <summary>The landblock in slot <paramref name="slot"/> and its offset.</summary>
    public readonly (LandblockEntry Entry, Vector2 Offset) Slot(int slot) => slot switch
    {
        0 => (_slot0!, _offset0),
        1 => (_slot1!, _offset1),
        2 => (_slot2!, _offset2),
        _ => (_slot3!, _offset3),
    };

    /// <summary>
    /// Sweeps the body (contact radius <paramref name="radius"/>) from <paramref name="p"/> along
    /// <paramref name="d"/> against every gathered wall in the band (a wall's end counts only if the move
    /// comes closer than <paramref name="graze"/> to it): the earliest contact below
    /// <paramref name="t"/>, with its normal; and the deepest overlap at <paramref name="p"/> beyond
    /// <paramref name="depth"/>, with the normal out of it.
    /// </summary>
    public readonly void Sweep(Vector2 p, Vector2 d, float radius, float graze, float zLow, float zHigh, ref float t, ref Vector2 normal, ref float depth, ref Vector2 outward)
    {
        // This sweep's own box (the move segment grown by the radius and the contact tolerance): a wall
        // outside it cannot be touched now, whatever the call's box says.
        float grow = radius + PhysicsConstants.ContactTolerance;
        Vector2 lo = Vector2.Min(p, p + d) - new Vector2(grow), hi = Vector2.Max(p, p + d) + new Vector2(grow);
        for (int i = 0; i < _count; i++)
        {
            (int slot, int index) = At(i);
            (LandblockEntry entry, Vector2 offset) = Slot(slot);
            Vector2 cellLo = lo - offset, cellHi = hi - offset;
            if ((index & ObjectFlag) != 0)
            {
                SweepWalls(entry.OutdoorObjects[index & ~ObjectFlag].Walls, offset, cellLo, cellHi, p, d, radius, graze, zLow, zHigh, ref t, ref normal, ref depth, ref outward);
                continue;
            }

            CellSurface cell = entry.Cells[index];
            SweepWalls(cell.Walls, offset, cellLo, cellHi, p, d, radius, graze, zLow, zHigh, ref t, ref normal, ref depth, ref outward);
            foreach (ObjectSurface o in cell.Objects)
            {
                SweepWalls(o.Walls, offset, cellLo, cellHi, p, d, radius, graze, zLow, zHigh, ref t, ref normal, ref depth, ref outward);
            }
        }
    }

    /// <summary>One cell's or object's walls (landblock frame <paramref name="offset"/> from the move's) in the sweep's box and band.</summary>
    private static void SweepWalls(
        CellWalls walls, Vector2 offset, Vector2 cellLo, Vector2 cellHi, Vector2 p, Vector2 d, float radius, float graze, float zLow, float zHigh,
        ref float t, ref Vector2 normal, ref float depth, ref Vector2 outward)
    {
        if (walls.Min.X > cellHi.X || walls.Max.X < cellLo.X || walls.Min.Y > cellHi.Y || walls.Max.Y < cellLo.Y)
        {
            return;
        }

        ReadOnlySpan<Vector3> vertices = walls.Vertices;
        foreach (ref readonly WallPolygon wall in walls.Polygons.AsSpan())
        {
            if (wall.ZMax <= zLow || wall.ZMin >= zHigh
                || wall.Min.X > cellHi.X || wall.Max.X < cellLo.X || wall.Min.Y > cellHi.Y || wall.Max.Y < cellLo.Y)
            {
                continue;
            }

            if (wall.IsUpright)
            {
                // A cylinder (Radius > 0) is met at the sum of the radii, and so is its graze: the graze is
                // measured from the contact radius, else every move coming no nearer the axis than the body's
                // own graze was taken for a graze and the body walked into the trunk up to its own radius.
                BodySweep.SweepSegment(p, d, wall.A + offset, wall.B + offset, radius + wall.Radius, graze + wall.Radius, ref t, ref normal, ref depth, ref outward);
            }
            else
            {
                BodySweep.SweepPolygon(vertices.Slice(wall.First, wall.Count), offset, p, d, radius, graze, zLow, zHigh, ref t, ref normal, ref depth, ref outward);
            }
        }
    }
}
