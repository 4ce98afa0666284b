using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Everything the engine holds for one registered landblock, with the lookups Resolve needs
/// prepared once: cells by id, each portal's neighbour, and which cells' floors lie over each
/// outdoor cell. Immutable after construction.
/// </summary>
internal sealed class LandblockEntry
{
    /// <summary>Portal target index meaning "out of the building, onto the terrain".</summary>
    public const int OutdoorTarget = -1;

    /// <summary>Portal target index meaning "a cell the engine does not have".</summary>
    public const int MissingCell = -2;

    private readonly Dictionary<uint, int> _indexById;

    /// <param name="x">Landblock X.</param>
    /// <param name="y">Landblock Y.</param>
    /// <param name="terrain">Its terrain.</param>
    /// <param name="cells">Its cells, ascending ids (with their objects).</param>
    /// <param name="outdoorObjects">Its own outdoor objects, then the neighbours' that reach over it (moved into its frame).</param>
    /// <param name="ownObjects">How many of <paramref name="outdoorObjects"/> are its own.</param>
    public LandblockEntry(int x, int y, TerrainSurface terrain, CellSurface[] cells, ObjectSurface[] outdoorObjects, int ownObjects)
    {
        OwnObjectCount = ownObjects;
        X = x;
        Y = y;
        Terrain = terrain;
        Cells = cells;
        OutdoorObjects = outdoorObjects;
        _indexById = new Dictionary<uint, int>(cells.Length);
        for (int i = 0; i < cells.Length; i++)
        {
            _indexById.Add(cells[i].CellId, i);
        }

        PortalTargets = new int[cells.Length][];
        for (int i = 0; i < cells.Length; i++)
        {
            IReadOnlyList<CellPortalInfo> portals = cells[i].Portals;
            var targets = new int[portals.Count];
            for (int k = 0; k < targets.Length; k++)
            {
                uint target = portals[k].TargetCellId;
                targets[k] = (target & 0xFFFF) == CellIds.OutdoorPortalTarget ? OutdoorTarget
                    : _indexById.TryGetValue(target, out int index) ? index
                    : MissingCell;
            }

            PortalTargets[i] = targets;
        }

        EntryBuckets = BuildBuckets(cells, static c => c.HasFloor ? (c.FloorMin, c.FloorMax) : null);
        WallBuckets = BuildBuckets(cells, static c => c.Walls.Polygons.Length > 0 ? (c.Walls.Min, c.Walls.Max) : null);
        (ObjectGridStarts, ObjectGridItems) = BuildObjectGrid(outdoorObjects);
        ObjectBoxes = Array.ConvertAll(outdoorObjects, static o => new ObjectBox(o));
        ObjectCells = ObjectCellMask(ObjectGridStarts);
    }

    /// <summary>Squares per side of the outdoor objects' fine grid (<see cref="ObjectGridSize"/> metres each).</summary>
    public const int ObjectGridSide = 48;

    /// <summary>Side of a square of the outdoor objects' fine grid, metres.</summary>
    public const float ObjectGridSize = PhysicsConstants.LandblockSize / ObjectGridSide;

    public int X { get; }

    public int Y { get; }

    public TerrainSurface Terrain { get; }

    /// <summary>The landblock's cells, in ascending id order.</summary>
    public CellSurface[] Cells { get; }

    /// <summary>Per cell, per portal: index of the neighbour in <see cref="Cells"/>, <see cref="OutdoorTarget"/> or <see cref="MissingCell"/>.</summary>
    public int[][] PortalTargets { get; }

    /// <summary>
    /// Per outdoor cell (index <see cref="CellIds.OutdoorCellNumber"/> − 1): the indices of the cells whose floor bounds overlap it.
    /// Outdoor movers test only these, so cells far away cost nothing.
    /// </summary>
    public int[][] EntryBuckets { get; }

    /// <summary>
    /// Per outdoor cell: the indices of the cells whose walls' bounds overlap it (clamped to the
    /// landblock). A body outdoors meets only these cells' walls.
    /// </summary>
    public int[][] WallBuckets { get; }

    /// <summary>
    /// The objects standing outdoors over this landblock, in its frame: its own (a <c>LandBlockInfo</c>'s
    /// objects and building shells; the first <see cref="OwnObjectCount"/>), then those of its
    /// neighbours whose bounds reach over it, moved into its frame.
    /// </summary>
    public ObjectSurface[] OutdoorObjects { get; }

    /// <summary>The boxes of <see cref="OutdoorObjects"/>, by the same index, in one array: a move's tests read them, not the objects.</summary>
    public ObjectBox[] ObjectBoxes { get; }

    /// <summary>How many of <see cref="OutdoorObjects"/> are the landblock's own.</summary>
    public int OwnObjectCount { get; }

    /// <summary>This landblock with <paramref name="reaching"/> as the neighbours' objects over it (its own kept): a new entry.</summary>
    public LandblockEntry WithNeighbourObjects(ObjectSurface[] reaching) =>
        new(X, Y, Terrain, Cells, [.. OutdoorObjects.AsSpan(0, OwnObjectCount), .. reaching], OwnObjectCount);

    /// <summary>
    /// The outdoor objects' fine grid (<see cref="ObjectGridSide"/>² squares of <see cref="ObjectGridSize"/> m,
    /// compressed rows): the objects over square k (index column·side + row) are
    /// <c>ObjectGridItems[ObjectGridStarts[k] .. ObjectGridStarts[k + 1]]</c>, those whose bounds (and floors'
    /// bounds) overlap it, clamped to the landblock. A point mover's floor and wall questions and the
    /// body's gathering of object walls look only at these; empty when the landblock has no outdoor objects.
    /// </summary>
    public int[] ObjectGridStarts { get; }

    /// <inheritdoc cref="ObjectGridStarts"/>
    public int[] ObjectGridItems { get; }

    /// <summary>
    /// Per outdoor cell (bit <see cref="CellIds.OutdoorCellNumber"/> − 1): set when a square of the fine
    /// grid on the cell or within one square of it lists an outdoor object. A box that reaches less than
    /// <see cref="ObjectCellReach"/> beyond a cell whose bit is clear meets no outdoor object: it stays on
    /// those squares. What lets a move far from every object skip them with one bit read.
    /// </summary>
    public ulong ObjectCells { get; }

    /// <summary>How far beyond an outdoor cell <see cref="ObjectCells"/> answers for, metres: one square, less twice <see cref="ObjectGeometry.NearMargin"/>.</summary>
    public const float ObjectCellReach = ObjectGridSize - (2f * ObjectGeometry.NearMargin);

    /// <summary>
    /// Whether an outdoor object may be listed on a square of the fine grid within <paramref name="reach"/>
    /// (metres, per axis) of <paramref name="local"/> (landblock-local): false is certain.
    /// </summary>
    public bool ObjectsMayBeWithin(Vector2 local, float reach) =>
        reach < ObjectCellReach ? (ObjectCells & (1UL << (int)(CellIds.OutdoorCellNumberUnchecked(local.X, local.Y) - 1))) != 0 : OutdoorObjects.Length > 0;

    /// <summary>The fine grid's column (or row) of a landblock-local coordinate, clamped to the landblock.</summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    public static int ObjectGridColumn(float coordinate) =>
        Math.Min((int)(Math.Clamp(coordinate, 0f, PhysicsConstants.LandblockSize) * (1f / ObjectGridSize)), ObjectGridSide - 1);

    /// <summary>The outdoor objects over fine-grid square (<paramref name="column"/>, <paramref name="row"/>).</summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    public ReadOnlySpan<int> ObjectsAt(int column, int row)
    {
        int k = (column * ObjectGridSide) + row;
        int start = ObjectGridStarts[k];
        return ObjectGridItems.AsSpan(start, ObjectGridStarts[k + 1] - start);
    }

    public bool TryGetCellIndex(uint cellId, out int index) => _indexById.TryGetValue(cellId, out index);

    /// <summary>The fine grid of <see cref="ObjectGridStarts"/>: each object over the squares its bounds and its floors' bounds (grown by the edge tolerance) cover.</summary>
    private static (int[] Starts, int[] Items) BuildObjectGrid(ObjectSurface[] objects)
    {
        if (objects.Length == 0)
        {
            return ([], []);
        }

        const int n = ObjectGridSide;
        var starts = new int[(n * n) + 1];
        var boxes = new (int X0, int X1, int Y0, int Y1)[objects.Length];
        for (int i = 0; i < objects.Length; i++)
        {
            ObjectSurface o = objects[i];
            Vector2 min = new(o.BoundsMin.X, o.BoundsMin.Y), max = new(o.BoundsMax.X, o.BoundsMax.Y);
            if (o.FloorMin.X <= o.FloorMax.X)
            {
                (min, max) = (Vector2.Min(min, o.FloorMin), Vector2.Max(max, o.FloorMax));
            }

            min -= new Vector2(PhysicsConstants.EdgeTolerance);
            max += new Vector2(PhysicsConstants.EdgeTolerance);
            boxes[i] = (ObjectGridColumn(min.X), ObjectGridColumn(max.X), ObjectGridColumn(min.Y), ObjectGridColumn(max.Y));
            for (int cx = boxes[i].X0; cx <= boxes[i].X1; cx++)
            {
                for (int cy = boxes[i].Y0; cy <= boxes[i].Y1; cy++)
                {
                    starts[(cx * n) + cy + 1]++;
                }
            }
        }

        for (int k = 0; k < n * n; k++)
        {
            starts[k + 1] += starts[k];
        }

        var items = new int[starts[n * n]];
        var next = starts[..(n * n)];
        for (int i = 0; i < objects.Length; i++)
        {
            for (int cx = boxes[i].X0; cx <= boxes[i].X1; cx++)
            {
                for (int cy = boxes[i].Y0; cy <= boxes[i].Y1; cy++)
                {
                    items[next[(cx * n) + cy]++] = i;
                }
            }
        }

        return (starts, items);
    }

    /// <summary><see cref="ObjectCells"/> of a fine grid (<see cref="ObjectGridStarts"/>; empty: no objects).</summary>
    private static ulong ObjectCellMask(int[] starts)
    {
        if (starts.Length == 0)
        {
            return 0;
        }

        const int perCell = ObjectGridSide / PhysicsConstants.CellsPerSide;
        ulong mask = 0;
        for (int cx = 0; cx < PhysicsConstants.CellsPerSide; cx++)
        {
            for (int cy = 0; cy < PhysicsConstants.CellsPerSide; cy++)
            {
                int x0 = Math.Max((cx * perCell) - 1, 0), x1 = Math.Min(((cx + 1) * perCell) + 1, ObjectGridSide);
                int y0 = Math.Max((cy * perCell) - 1, 0), y1 = Math.Min(((cy + 1) * perCell) + 1, ObjectGridSide);
                for (int x = x0; x < x1; x++)
                {
                    if (starts[(x * ObjectGridSide) + y0] != starts[(x * ObjectGridSide) + y1])
                    {
                        mask |= 1UL << ((cx * PhysicsConstants.CellsPerSide) + cy);
                    }
                }
            }
        }

        return mask;
    }

    /// <summary>Per outdoor cell, the items whose bounds (from <paramref name="bounds"/>; null: none) overlap it.</summary>
    private static int[][] BuildBuckets(CellSurface[] cells, Func<CellSurface, (Vector2 Min, Vector2 Max)?> bounds)
    {
        const int n = PhysicsConstants.CellsPerSide;
        var lists = new List<int>?[n * n];
        for (int i = 0; i < cells.Length; i++)
        {
            if (bounds(cells[i]) is not (Vector2 min, Vector2 max))
            {
                continue;
            }

            int cx0 = CellIds.OutdoorColumn(min.X), cx1 = CellIds.OutdoorColumn(max.X);
            int cy0 = CellIds.OutdoorColumn(min.Y), cy1 = CellIds.OutdoorColumn(max.Y);
            for (int cx = cx0; cx <= cx1; cx++)
            {
                for (int cy = cy0; cy <= cy1; cy++)
                {
                    (lists[(cx * n) + cy] ??= []).Add(i);
                }
            }
        }

        var buckets = new int[n * n][];
        for (int b = 0; b < buckets.Length; b++)
        {
            buckets[b] = lists[b]?.ToArray() ?? [];
        }

        return buckets;
    }
}

/// <summary>
/// An outdoor object's walls' bounds seen from above (empty when it has none), the height range of all
/// of it, and its floors' bounds, landblock-local metres: what a move tests before it reads the object
/// (<see cref="LandblockEntry.ObjectBoxes"/>).
/// </summary>
internal readonly struct ObjectBox(ObjectSurface o)
{
    public readonly Vector2 WallMin = o.Walls.Min;
    public readonly Vector2 WallMax = o.Walls.Max;
    public readonly float ZMin = o.BoundsMin.Z;
    public readonly float ZMax = o.BoundsMax.Z;
    public readonly Vector2 FloorMin = o.FloorMin;
    public readonly Vector2 FloorMax = o.FloorMax;
}
