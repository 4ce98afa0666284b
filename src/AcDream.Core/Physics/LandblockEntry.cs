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
        ObjectBuckets = BuildBuckets(outdoorObjects, static o => (new Vector2(o.BoundsMin.X, o.BoundsMin.Y), new Vector2(o.BoundsMax.X, o.BoundsMax.Y)));
    }

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

    /// <summary>How many of <see cref="OutdoorObjects"/> are the landblock's own.</summary>
    public int OwnObjectCount { get; }

    /// <summary>This landblock with <paramref name="reaching"/> as the neighbours' objects over it (its own kept): a new entry.</summary>
    public LandblockEntry WithNeighbourObjects(ObjectSurface[] reaching) =>
        new(X, Y, Terrain, Cells, [.. OutdoorObjects.AsSpan(0, OwnObjectCount), .. reaching], OwnObjectCount);

    /// <summary>Per outdoor cell: the indices of the outdoor objects whose bounds overlap it (clamped to the landblock). A move looks only at these.</summary>
    public int[][] ObjectBuckets { get; }

    public bool TryGetCellIndex(uint cellId, out int index) => _indexById.TryGetValue(cellId, out index);

    /// <summary>Per outdoor cell, the items whose bounds (from <paramref name="bounds"/>; null: none) overlap it.</summary>
    private static int[][] BuildBuckets<T>(T[] cells, Func<T, (Vector2 Min, Vector2 Max)?> bounds)
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
