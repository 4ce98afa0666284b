using System.Numerics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.World;

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
    /// <param name="outdoorObjects">Its outdoor objects (its <c>LandBlockInfo</c>'s objects and building shells).</param>
    public LandblockEntry(int x, int y, TerrainSurface terrain, CellSurface[] cells, ObjectSurface[] outdoorObjects)
    {
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

        EntryBuckets = BuildBuckets(cells);
        CellGroups = Groups(PortalTargets, out int outdoors);
        MetOutdoors = Array.ConvertAll(CellGroups, g => g == outdoors);
        CellWallBounds = Array.ConvertAll(cells, static c => c.WallBounds());
        Reaching = ReachingObjects.Build(cells);
        var cellBoxes = new (Vector2 Min, Vector2 Max)[cells.Length];
        var outdoorCellBoxes = new (Vector2 Min, Vector2 Max)[cells.Length];
        Vector2 min = new(float.MaxValue), max = new(float.MinValue);
        for (int i = 0; i < cells.Length; i++)
        {
            cellBoxes[i] = (CellWallBounds[i].Min, CellWallBounds[i].Max);
            outdoorCellBoxes[i] = MetOutdoors[i] ? cellBoxes[i] : (new Vector2(float.MaxValue), new Vector2(float.MinValue));
            (min, max) = (Vector2.Min(min, outdoorCellBoxes[i].Min), Vector2.Max(max, outdoorCellBoxes[i].Max));
        }

        CellWalls = BoxGrid.Build(cellBoxes, CellWallSquare);
        OutdoorCellWalls = BoxGrid.Build(outdoorCellBoxes, CellWallSquare);
        var objectBoxes = new (Vector2 Min, Vector2 Max)[outdoorObjects.Length];
        for (int i = 0; i < outdoorObjects.Length; i++)
        {
            objectBoxes[i] = ObjectBox.GridBounds(outdoorObjects[i]);
            (min, max) = (Vector2.Min(min, objectBoxes[i].Min), Vector2.Max(max, objectBoxes[i].Max));
        }

        Objects = BoxGrid.Fixed(objectBoxes, ObjectGridSide, ObjectGridSize);
        ObjectBoxes = Array.ConvertAll(outdoorObjects, static o => new ObjectBox(o));
        HasSteep = Array.Exists(cells, static c => c.Walls.HasSteep || Array.Exists(c.Objects, static o => o.Walls.HasSteep))
            || Array.Exists(outdoorObjects, static o => o.Walls.HasSteep);
        FloorsBeyondWalls = Array.Exists(ObjectBoxes, static b => Beyond(b.FloorMin, b.FloorMax, b.WallMin, b.WallMax))
            || Enumerable.Range(0, cells.Length).Any(i => MetOutdoors[i] && Beyond(cells[i].FloorMin, cells[i].FloorMax, CellWallBounds[i].Min, CellWallBounds[i].Max));
        ObjectCells = outdoorObjects.Length == 0 ? 0 : ObjectCellMask(Objects);
        (OutdoorMin, OutdoorMax) = (min, max);
    }

    /// <summary>Squares per side of the outdoor objects' fine grid (<see cref="ObjectGridSize"/> metres each).</summary>
    public const int ObjectGridSide = 48;

    /// <summary>Side of a square of the outdoor objects' fine grid, metres.</summary>
    public const float ObjectGridSize = PhysicsConstants.LandblockSize / ObjectGridSide;

    /// <summary>Side of a square of the cells' wall grids, metres (about a room's width).</summary>
    private const float CellWallSquare = 4f;

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

    /// <summary>Per cell, its building: cells joined through portals share a group (the lowest index among them).</summary>
    public int[] CellGroups { get; }

    /// <summary>
    /// Per cell: whether outdoor movers meet its walls: it belongs to a building, a group of cells joined
    /// by portals of which one leads to the outdoors. A dungeon's cells (no way out but by portal objects)
    /// are met only from inside.
    /// </summary>
    public bool[] MetOutdoors { get; }

    /// <summary>Per cell, the objects standing in other cells that reach into its space (<see cref="ReachingObjects"/>).</summary>
    public ReachingObject[][] Reaching { get; }

    /// <summary>Per cell, the bounds of its walls and its objects' walls (<see cref="CellSurface.WallBounds"/>), in one array.</summary>
    public WallBounds[] CellWallBounds { get; }

    /// <summary>The cells' walls and their objects' walls, by their bounds seen from above (<see cref="CellWallBounds"/>): what a body indoors meets. Null when no cell has walls.</summary>
    public BoxGrid? CellWalls { get; }

    /// <summary>As <see cref="CellWalls"/>, the cells <see cref="MetOutdoors"/> only: what a body outdoors meets of the cells.</summary>
    public BoxGrid? OutdoorCellWalls { get; }

    /// <summary>The objects standing outdoors in this landblock (its <c>LandBlockInfo</c>'s objects and building shells), in its frame.</summary>
    public ObjectSurface[] OutdoorObjects { get; }

    /// <summary>The boxes of <see cref="OutdoorObjects"/>, by the same index, in one array: a move's tests read them, not the objects.</summary>
    public ObjectBox[] ObjectBoxes { get; }

    /// <summary>Whether any wall of its cells and objects is a face a fall may land on (<see cref="CellWalls.HasSteep"/>).</summary>
    public bool HasSteep { get; }

    /// <summary>
    /// Whether an outdoor object's floors, or those of a cell a body outdoors meets, reach past their walls' bounds (a slab,
    /// a tread beyond its sides): where no wall is near a body, such a floor may still be under its footprint (footing).
    /// </summary>
    public bool FloorsBeyondWalls { get; }

    /// <summary>Whether floor bounds <paramref name="floorMin"/>–<paramref name="floorMax"/> (not empty) reach past wall bounds <paramref name="wallMin"/>–<paramref name="wallMax"/>.</summary>
    private static bool Beyond(Vector2 floorMin, Vector2 floorMax, Vector2 wallMin, Vector2 wallMax) =>
        floorMin.X <= floorMax.X && (floorMin.X < wallMin.X || floorMin.Y < wallMin.Y || floorMax.X > wallMax.X || floorMax.Y > wallMax.Y);

    /// <summary>
    /// The outdoor objects' fine grid (<see cref="ObjectGridSide"/>² squares of <see cref="ObjectGridSize"/> m
    /// from the landblock's corner): each object over the squares its bounds and its floors' bounds (grown by
    /// the edge tolerance) overlap, those beyond the landblock over its border squares. A point mover's floor
    /// and wall questions and the body's object walls look only at these.
    /// </summary>
    public BoxGrid Objects { get; }

    /// <summary>
    /// Per outdoor cell (bit <see cref="CellIds.OutdoorCellNumber"/> − 1): set when a square of the fine
    /// grid on the cell or within one square of it lists an outdoor object. A box that reaches less than
    /// <see cref="ObjectCellReach"/> beyond a cell whose bit is clear meets no outdoor object of this
    /// landblock: it stays on those squares. What lets a move far from every object skip them with one bit read.
    /// </summary>
    public ulong ObjectCells { get; }

    /// <summary>How far beyond an outdoor cell <see cref="ObjectCells"/> answers for, metres: one square, less twice <see cref="PhysicsConstants.NearMargin"/>.</summary>
    public const float ObjectCellReach = ObjectGridSize - (2f * PhysicsConstants.NearMargin);

    /// <summary>
    /// Bounds seen from above (landblock-local metres) of everything here that outdoor movers meet: the outdoor
    /// objects (with their floors) and the walls of the cells <see cref="MetOutdoors"/>. Empty (min &gt; max) when
    /// there is nothing; never more than <see cref="PhysicsConstants.MaxSeamReach"/> past the landblock's edges.
    /// A mover in a neighbouring landblock looks here only when its box meets these bounds.
    /// </summary>
    public Vector2 OutdoorMin { get; }

    /// <inheritdoc cref="OutdoorMin"/>
    public Vector2 OutdoorMax { get; }

    /// <summary>
    /// Whether an outdoor object of this landblock may be listed on a square of the fine grid within
    /// <paramref name="reach"/> (metres, per axis) of <paramref name="local"/> (landblock-local): false is certain.
    /// </summary>
    public bool ObjectsMayBeWithin(Vector2 local, float reach) =>
        reach < ObjectCellReach ? (ObjectCells & (1UL << (int)(CellIds.OutdoorCellNumberUnchecked(local.X, local.Y) - 1))) != 0 : OutdoorObjects.Length > 0;

    /// <summary>Whether the box <paramref name="lo"/>–<paramref name="hi"/> (this landblock's frame) meets <see cref="OutdoorMin"/>–<see cref="OutdoorMax"/>.</summary>
    public bool OutdoorsOverlaps(Vector2 lo, Vector2 hi) =>
        Boxes.Overlaps(OutdoorMin, OutdoorMax, lo, hi);

    public bool TryGetCellIndex(uint cellId, out int index) => _indexById.TryGetValue(cellId, out index);

    /// <summary><see cref="ObjectCells"/> of the outdoor objects' fine grid.</summary>
    private static ulong ObjectCellMask(BoxGrid grid)
    {
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
                    for (int y = y0; y < y1; y++)
                    {
                        if (grid.Lists(x, y))
                        {
                            mask |= 1UL << ((cx * PhysicsConstants.CellsPerSide) + cy);
                        }
                    }
                }
            }
        }

        return mask;
    }

    /// <summary>
    /// <see cref="CellGroups"/>: cells joined through portals (either way) share a group, numbered by their
    /// lowest cell index; <paramref name="outdoors"/>: the group of the cells joined to the outdoors (−1 when none).
    /// </summary>
    private static int[] Groups(int[][] portalTargets, out int outdoors)
    {
        int n = portalTargets.Length;
        var parent = new int[n + 1]; // n: the outdoors
        for (int i = 0; i <= n; i++)
        {
            parent[i] = i;
        }

        for (int i = 0; i < n; i++)
        {
            foreach (int target in portalTargets[i])
            {
                int other = target >= 0 ? target : target == OutdoorTarget ? n : -1;
                if (other >= 0)
                {
                    int a = Root(parent, i), b = Root(parent, other);
                    parent[Math.Max(a, b)] = Math.Min(a, b); // the lower index is the root
                }
            }
        }

        var groups = new int[n];
        for (int i = 0; i < n; i++)
        {
            groups[i] = Root(parent, i);
        }

        int outside = Root(parent, n);
        outdoors = outside == n ? -1 : outside;
        return groups;

        static int Root(int[] parent, int i)
        {
            while (parent[i] != i)
            {
                parent[i] = parent[parent[i]]; // path halving
                i = parent[i];
            }

            return i;
        }
    }

    /// <summary>Per outdoor cell, the cells whose floor bounds overlap it.</summary>
    private static int[][] BuildBuckets(CellSurface[] cells)
    {
        const int n = PhysicsConstants.CellsPerSide;
        var lists = new List<int>?[n * n];
        for (int i = 0; i < cells.Length; i++)
        {
            if (!cells[i].HasFloor)
            {
                continue;
            }

            (Vector2 min, Vector2 max) = (cells[i].FloorMin, cells[i].FloorMax);
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
    /// <summary>The box an object is listed by in the fine grid: its bounds and its floors' bounds, grown by the edge tolerance.</summary>
    public static (Vector2 Min, Vector2 Max) GridBounds(ObjectSurface o)
    {
        Vector2 min = new(o.BoundsMin.X, o.BoundsMin.Y), max = new(o.BoundsMax.X, o.BoundsMax.Y);
        if (o.FloorMin.X <= o.FloorMax.X)
        {
            (min, max) = (Vector2.Min(min, o.FloorMin), Vector2.Max(max, o.FloorMax));
        }

        return (min - new Vector2(PhysicsConstants.EdgeTolerance), max + new Vector2(PhysicsConstants.EdgeTolerance));
    }

    public readonly Vector2 WallMin = o.Walls.Min;
    public readonly Vector2 WallMax = o.Walls.Max;
    public readonly float ZMin = o.BoundsMin.Z;
    public readonly float ZMax = o.BoundsMax.Z;
    public readonly Vector2 FloorMin = o.FloorMin;
    public readonly Vector2 FloorMax = o.FloorMax;
}
