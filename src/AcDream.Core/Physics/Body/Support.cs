using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// The floors under a body's footprint (<see cref="MovementOptions.Footing"/>): every cell's or object's floor triangle
/// whose nearest point, seen from above, is within the support reach of the body's centre. Landblock-local metres;
/// allocation-free. Terrain is not among them: it lies under every outdoor centre, and the point's ground has it.
/// </summary>
internal static class Supports
{
    /// <summary>
    /// The steepest a floor rises per metre seen from above: tan of the walkable limit (normal Z ≥ <see cref="PhysicsConstants.FloorZ"/>),
    /// 1.1256, rounded up. A floor's plane under a centre up to the reach past its lowest edge is at most this times the reach below it.
    /// </summary>
    private const float MaxFloorSlope = 1.126f;

    /// <summary>
    /// The highest floor within the footprint's reach of its centre (landblock-local to <paramref name="place"/>) whose Z
    /// under the centre (<see cref="FloorTriangle.UnderCentre"/>) is in its band: indoors, the floors of the place's cell, of
    /// cell <paramref name="alsoCell"/> (the move's start, when another; −1: none) and, with <paramref name="building"/>, of
    /// the other cells of its building, with their objects'; outdoors, the outdoor objects' floors and the buildings' cells'
    /// floors, across seams too.
    /// </summary>
    public static Support Highest(ref Neighbourhood lands, in Place place, int alsoCell, in Footprint footprint, bool building = false)
    {
        var scan = new HighestScan
        {
            Best = new Support { Z = float.NegativeInfinity, CellIndex = -1 }, P = footprint.Centre, Reach = footprint.Reach,
            Low = footprint.Low, High = footprint.High,
            Lo = footprint.Centre - new Vector2(footprint.Reach), Hi = footprint.Centre + new Vector2(footprint.Reach),
        };
        Visit(ref lands, in place, alsoCell, building, ref scan);
        return scan.Best;
    }

    /// <summary>
    /// The edge a body left: among the floors within <paramref name="reach"/> of <paramref name="start"/> whose Z there is
    /// within the ground tolerance of <paramref name="level"/> (what it stood on), the one nearest <paramref name="end"/>;
    /// its outward unit normal seen from above, from its nearest point to <paramref name="end"/> (zero when none is, or
    /// <paramref name="end"/> is over it), whose floor it is and that nearest point.
    /// </summary>
    public static LeftEdge Edge(ref Neighbourhood lands, in Place place, Vector2 start, Vector2 end, float reach, float level)
    {
        var scan = new EdgeScan
        {
            Start = start, End = end, Reach = reach, Level = level, Distance = float.PositiveInfinity,
            Lo = Vector2.Min(start, end) - new Vector2(reach), Hi = Vector2.Max(start, end) + new Vector2(reach),
        };
        Visit(ref lands, in place, -1, false, ref scan);
        Vector2 away = end - scan.Nearest;
        Vector2 normal = scan.Distance < float.PositiveInfinity && away != Vector2.Zero ? Vector2.Normalize(away) : Vector2.Zero;
        return new LeftEdge(normal, scan.Floor, scan.Nearest);
    }

    /// <summary>Hands every floor whose bounds meet the scan's box (<see cref="IFloorScan.Lo"/>–<see cref="IFloorScan.Hi"/>) to <paramref name="scan"/>, with the offset of its frame.</summary>
    private static void Visit<T>(ref Neighbourhood lands, in Place place, int alsoCell, bool building, ref T scan)
        where T : struct, IFloorScan
    {
        LandblockEntry entry = place.Entry;
        Vector2 lo = scan.Lo, hi = scan.Hi;
        if (place.CellIndex >= 0)
        {
            Cell(entry, place.CellIndex, ref scan);
            if (alsoCell >= 0 && alsoCell != place.CellIndex)
            {
                Cell(entry, alsoCell, ref scan);
            }

            if (building)
            {
                // The other cells of its building whose floors reach the box: at a doorway or over an opening's edge the
                // floor beyond holds the body too, whichever cell its centre was found in.
                int group = entry.CellGroups[place.CellIndex];
                for (BoxGrid.Cursor near = entry.CellWalls is BoxGrid cells ? cells.Near(lo, hi) : default; near.MoveNext();)
                {
                    int c = near.Current;
                    CellSurface other = entry.Cells[c];
                    if (c != place.CellIndex && c != alsoCell && entry.CellGroups[c] == group
                        && Boxes.Overlaps(other.FloorMin, other.FloorMax, lo, hi))
                    {
                        Cell(entry, c, ref scan);
                    }
                }
            }

            return;
        }

        Outdoors(entry, lo, hi, Vector2.Zero, ref scan);
        if (lands.ReachInto(entry).Meets(lo, hi))
        {
            SeamNeighbours across = Neighbourhood.Across(ref lands, entry, lo, hi);
            while (across.MoveNext())
            {
                Outdoors(across.Current, lo - across.Offset, hi - across.Offset, across.Offset, ref scan);
            }
        }
    }

    private static void Cell<T>(LandblockEntry entry, int index, ref T scan)
        where T : struct, IFloorScan
    {
        CellSurface cell = entry.Cells[index];
        if (scan.Spans(cell.FloorZMin, cell.FloorZMax))
        {
            scan.Scan(cell.Floors, Vector2.Zero, SurfaceKind.CellFloor, cell.CellId, index);
        }

        foreach (ObjectSurface o in cell.Objects)
        {
            if (scan.Spans(o.BoundsMin.Z, o.BoundsMax.Z))
            {
                scan.Scan(o.Floors, Vector2.Zero, SurfaceKind.ObjectFloor, o.ObjectId, index);
            }
        }
    }

    private static void Outdoors<T>(LandblockEntry entry, Vector2 lo, Vector2 hi, Vector2 offset, ref T scan)
        where T : struct, IFloorScan
    {
        if (entry.OutdoorCellWalls is BoxGrid cells)
        {
            // A building's cells' floors, where one reaches out past its doorway's plane (the threshold): they hold an
            // outdoor body there, which stays outdoors (its centre decides its cell).
            for (BoxGrid.Cursor near = cells.Near(lo, hi); near.MoveNext();)
            {
                CellSurface cell = entry.Cells[near.Current];
                if (Boxes.Overlaps(cell.FloorMin, cell.FloorMax, lo, hi))
                {
                    scan.Scan(cell.Floors, offset, SurfaceKind.CellFloor, cell.CellId, -1);
                }
            }
        }

        if (entry.OutdoorObjects.Length == 0)
        {
            return;
        }

        for (BoxGrid.Cursor near = entry.Objects.Near(lo, hi); near.MoveNext();)
        {
            ref readonly ObjectBox b = ref entry.ObjectBoxes[near.Current];
            if (Boxes.Overlaps(b.FloorMin, b.FloorMax, lo, hi))
            {
                ObjectSurface o = entry.OutdoorObjects[near.Current];
                scan.Scan(o.Floors, offset, SurfaceKind.ObjectFloor, o.ObjectId, -1);
            }
        }
    }

    /// <summary>What is done with each floor near the body (its triangles in a frame <c>offset</c> from the body's).</summary>
    private interface IFloorScan
    {
        /// <summary>The south-west corner of the box the floors are looked for in (landblock-local metres).</summary>
        Vector2 Lo { get; }

        /// <summary>Its north-east corner.</summary>
        Vector2 Hi { get; }

        /// <summary>Whether floors between the two heights may matter (a whole cell's or object's are skipped when not).</summary>
        bool Spans(float zMin, float zMax);

        void Scan(ReadOnlySpan<FloorTriangle> floors, Vector2 offset, SurfaceKind kind, uint id, int cellIndex);
    }

    /// <summary>Keeps the highest floor within reach between the two heights.</summary>
    private struct HighestScan : IFloorScan
    {
        public Vector2 Lo { get; init; }
        public Vector2 Hi { get; init; }
        public Support Best;
        public Vector2 P;
        public float Reach;
        public float Low;
        public float High;

        public readonly bool Spans(float zMin, float zMax) => zMax >= Low && zMin - (Reach * MaxFloorSlope) <= High && zMax > Best.Z;

        public void Scan(ReadOnlySpan<FloorTriangle> floors, Vector2 offset, SurfaceKind kind, uint id, int cellIndex)
        {
            Vector2 p = P - offset;
            float reach2 = Reach * Reach;
            foreach (ref readonly FloorTriangle t in floors)
            {
                if (t.ZMax < Low || t.ZMin - (Reach * MaxFloorSlope) > High || t.ZMax <= Best.Z
                    || p.X < t.Min.X - Reach || p.Y < t.Min.Y - Reach || p.X > t.Max.X + Reach || p.Y > t.Max.Y + Reach)
                {
                    continue;
                }

                Vector2 n = t.Nearest(p);
                float z = t.UnderCentre(p);
                if (Vector2.DistanceSquared(n, p) <= reach2 && z >= Low && z <= High && z > Best.Z)
                {
                    Best = new Support { Z = z, Found = true, Floor = new SurfaceContact(kind, id, t.Normal), CellIndex = cellIndex };
                }
            }
        }
    }

    /// <summary>Keeps the floor at the level stood on nearest the end.</summary>
    private struct EdgeScan : IFloorScan
    {
        public Vector2 Lo { get; init; }
        public Vector2 Hi { get; init; }
        public Vector2 Start;
        public Vector2 End;
        public float Reach;
        public float Level;
        public float Distance;
        public Vector2 Nearest;
        public SurfaceContact Floor;

        public readonly bool Spans(float zMin, float zMax) => zMax >= Level - PhysicsConstants.GroundTolerance && zMin - (Reach * MaxFloorSlope) <= Level + PhysicsConstants.GroundTolerance;

        public void Scan(ReadOnlySpan<FloorTriangle> floors, Vector2 offset, SurfaceKind kind, uint id, int cellIndex)
        {
            Vector2 start = Start - offset, end = End - offset;
            foreach (ref readonly FloorTriangle t in floors)
            {
                Vector2 held = t.Nearest(start);
                if (Vector2.DistanceSquared(held, start) > Reach * Reach || MathF.Abs(t.UnderCentre(start) - Level) > PhysicsConstants.GroundTolerance)
                {
                    continue;
                }

                Vector2 n = t.Nearest(end);
                float d = Vector2.DistanceSquared(n, end);
                if (d < Distance)
                {
                    (Distance, Nearest, Floor) = (d, n + offset, new SurfaceContact(kind, id, t.Normal));
                }
            }
        }
    }
}

/// <summary>
/// What <see cref="Supports.Highest"/> looks for: the floors within <see cref="Reach"/> of <see cref="Centre"/> seen from
/// above (landblock-local metres) whose Z under the centre is between <see cref="Low"/> and <see cref="High"/>.
/// </summary>
internal readonly record struct Footprint(Vector2 Centre, float Reach, float Low, float High);

/// <summary>
/// The edge of the floor a body left (<see cref="Supports.Edge"/>): its outward unit normal seen from above (zero for
/// none), whose floor it is, and its point nearest where the body went (landblock-local metres).
/// </summary>
internal readonly record struct LeftEdge(Vector2 Normal, SurfaceContact Floor, Vector2 Nearest);

/// <summary>A floor under a body's footprint: its Z (metres), whether found, what it is (kind, id, normal), and the indoor cell that holds it (−1 outdoors).</summary>
internal struct Support
{
    public float Z;
    public bool Found;
    public SurfaceContact Floor;
    public int CellIndex;
}
