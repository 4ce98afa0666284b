using System.Numerics;
using AcDream.Core.Dat;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced): the body's slow reference.

/// <summary>
/// A slow, double-precision reference of the body model of <c>docs/physics.md</c>, written from its
/// description, not from the engine's code: an upright cylinder of radius r on the feet point; the
/// walls are wall polygons (landblock-local, taken from the world's own definition) cut to the band
/// [feet + step height, feet + height]; seen from above their edges are obstacles the centre stays r
/// away from. The body moves in <see cref="SubStep"/> (0.1 mm) sub-steps along its move; after each,
/// a centre closer than r to an edge is a contact: it is pushed out to exactly r (iterated over all
/// edges) and from then on the rest of the move is projected onto that wall. A contact whose projected
/// rest points into the wall touched before (a concave corner) or back against the move (wedged between
/// two walls met together) stops the body, and so does the <see cref="MaxContacts"/>-th contact. Walls
/// met together (within <see cref="Together"/> of travel) are resolved as one: the slide along the
/// latest alone, from the move as it was before the others.
/// </summary>
/// <remarks>
/// Two refinements keep it slow in principle but fast enough in practice, without changing what it
/// computes: a stretch of sub-steps that cannot bring any edge within r is skipped at once (the
/// distance to a segment is convex along a line, so it stays above its tangent), and the sub-step in
/// which a contact happens is halved until the contact is located to 1e-10 m, so the slide direction
/// at a rounded (convex) corner is not off by a sub-step's worth of angle.
/// </remarks>
internal sealed class ReferenceBody
{
    /// <summary>The game's walkable limit: a polygon whose unit normal Z is at least this is a floor, not a wall.</summary>
    public const double FloorZ = 0.66417414618662751;

    /// <summary>Sub-step length, metres.</summary>
    public const double SubStep = 1e-4;

    /// <summary>The most walls one move touches; the last of them stops the body.</summary>
    public const int MaxContacts = 4;

    /// <summary>How far, metres, a physics polygon may lie off a portal's plane and still be the doorway's cover.</summary>
    public const double CoverTolerance = 0.01;

    /// <summary>
    /// A later contact whose slide points back against the move (its cosine with the move below this)
    /// stops the body: it is wedged between walls met together, whose projections in turn would send it
    /// backwards.
    /// </summary>
    public const double Wedged = 1e-3;

    /// <summary>
    /// A contact that comes within this travel (metres) of the one before is met together with it: the
    /// slide is then this wall's alone (the projection of the move as it was before the other's), which is
    /// the one that can clear the other; if it does not, the body is wedged and stops.
    /// </summary>
    public const double Together = 1e-4;

    /// <summary>A centre closer than r by less than this (metres) is not yet a contact: double rounding.</summary>
    private const double Touch = 1e-9;

    private readonly Wall[] _walls;

    /// <summary>A reference over wall polygons in landblock-local metres.</summary>
    public ReferenceBody(IEnumerable<Vec3[]> walls)
    {
        _walls = walls.Select(v => new Wall(v)).ToArray();
    }

    /// <summary>The wall polygons, landblock-local.</summary>
    public IEnumerable<Vec3[]> Walls => _walls.Select(w => w.Vertices);

    /// <summary>The walls of every cell given (see <see cref="WallsOf"/>), placed in landblock-local metres.</summary>
    public static ReferenceBody FromCells(IEnumerable<(EnvCell Cell, CellStruct Struct)> cells) =>
        new(cells.SelectMany(c => WallsOf(c.Cell, c.Struct)));

    /// <summary>
    /// A cell's walls: every physics polygon, placed in double precision, that has an area and is not a
    /// floor (unit normal Z ≥ <see cref="FloorZ"/>) and does not cover one of the cell's portals (every
    /// vertex within <see cref="CoverTolerance"/> of the portal's plane, its centroid inside the portal).
    /// </summary>
    public static List<Vec3[]> WallsOf(EnvCell cell, CellStruct cellStruct)
    {
        var portals = new List<Vec3[]>();
        foreach (CellPortal portal in cell.CellPortals)
        {
            portals.Add(Placed(cell.Position, cellStruct, cellStruct.Polygons[portal.PolygonId]));
        }

        var walls = new List<Vec3[]>();
        foreach (Polygon polygon in cellStruct.PhysicsPolygons.OrderBy(p => p.Key).Select(p => p.Value))
        {
            Vec3[] v = Placed(cell.Position, cellStruct, polygon);
            Vec3 n = Newell(v);
            double length = n.Length;
            if (length == 0 || n.Z / length >= FloorZ || portals.Any(p => Covers(p, v)))
            {
                continue;
            }

            walls.Add(v);
        }

        return walls;
    }

    /// <summary>A cell-local point placed by <paramref name="frame"/> in double precision (the quaternion normalised).</summary>
    public static Vec3 Place(Frame frame, Vector3 local)
    {
        Quaternion q = frame.Orientation;
        double qx = q.X, qy = q.Y, qz = q.Z, qw = q.W;
        double norm = Math.Sqrt((qx * qx) + (qy * qy) + (qz * qz) + (qw * qw));
        qx /= norm;
        qy /= norm;
        qz /= norm;
        qw /= norm;

        // v' = v + 2w (q × v) + 2 q × (q × v), q the vector part of a unit quaternion.
        double vx = local.X, vy = local.Y, vz = local.Z;
        double cx = (qy * vz) - (qz * vy), cy = (qz * vx) - (qx * vz), cz = (qx * vy) - (qy * vx);
        double ccx = (qy * cz) - (qz * cy), ccy = (qz * cx) - (qx * cz), ccz = (qx * cy) - (qy * cx);
        return new Vec3(
            frame.Origin.X + vx + (2 * ((qw * cx) + ccx)),
            frame.Origin.Y + vy + (2 * ((qw * cy) + ccy)),
            frame.Origin.Z + vz + (2 * ((qw * cz) + ccz)));
    }

    /// <summary>The edges of every wall cut to the band [<paramref name="zLow"/>, <paramref name="zHigh"/>], seen from above.</summary>
    public List<(Vec2 A, Vec2 B)> Edges(double zLow, double zHigh) => EdgesNear(zLow, zHigh, default, double.PositiveInfinity);

    /// <summary>
    /// The distance from <paramref name="p"/> to the nearest band-cut wall edge (infinity when none):
    /// a body of radius r there overlaps the walls by r − this.
    /// </summary>
    public double Clearance(Vec2 p, double zLow, double zHigh)
    {
        double best = double.PositiveInfinity;
        foreach ((Vec2 a, Vec2 b) in EdgesNear(zLow, zHigh, p, 50))
        {
            best = Math.Min(best, Distance(p, a, b));
        }

        return best;
    }

    /// <summary>Whether the segment <paramref name="from"/> → <paramref name="to"/> meets a band-cut wall edge (touching counts).</summary>
    public bool Crosses(Vec2 from, Vec2 to, double zLow, double zHigh)
    {
        Vec2 centre = (from + to) * 0.5;
        double reach = (to - from).Length;
        foreach ((Vec2 a, Vec2 b) in EdgesNear(zLow, zHigh, centre, reach))
        {
            if (SegmentsMeet(from, to, a, b))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// Moves a body of <paramref name="radius"/> from <paramref name="start"/> by <paramref name="delta"/>
    /// (landblock-local metres) among the walls cut to the band [<paramref name="zLow"/>, <paramref name="zHigh"/>].
    /// </summary>
    public Result Move(Vec2 start, Vec2 delta, double zLow, double zHigh, double radius)
    {
        List<(Vec2 A, Vec2 B)> edges = EdgesNear(zLow, zHigh, start, delta.Length + radius + 0.01);
        Vec2 position = start, rest = delta, normal = default, unprojected = delta;
        Vec2? previous = null;
        int contacts = 0, idle = 0;
        for (int round = 0; ; round++)
        {
            double length = rest.Length;
            if (length <= 1e-12)
            {
                return new Result(position, contacts, normal, Stopped: false);
            }

            Vec2 direction = rest / length;
            double travelled = FreeTravel(edges, position, direction, length, radius);
            if (travelled >= length)
            {
                return new Result(position + rest, contacts, normal, Stopped: false);
            }

            // Contact: the sub-step found is halved down to the first touch, then pushed out exactly.
            position = PushOut(edges, position + (direction * travelled), radius);
            bool together = previous is not null && travelled < Together;
            rest = direction * (length - travelled);
            unprojected *= (length - travelled) / length;
            bool met = false;
            foreach (Vec2 n in ContactNormals(edges, position, direction, radius))
            {
                if (Dot(rest, n) >= 0)
                {
                    continue; // an earlier contact's slide already leaves this wall
                }

                met = true;

                contacts++;
                normal = n;
                if (together)
                {
                    rest = Project(unprojected, n); // met together with the one before: this wall's slide alone
                }
                else
                {
                    unprojected = rest;
                    rest = Project(rest, n);
                }

                bool wedged = !together && Dot(rest, delta) < Wedged * rest.Length * delta.Length; // (together: this slide alone is the move's own projection)
                if ((previous is Vec2 before && (Dot(rest, before) < 0 || wedged)) || contacts == MaxContacts)
                {
                    return new Result(position, contacts, normal, Stopped: true);
                }

                previous = n;
                together = true;
            }

            idle = met ? 0 : idle + 1;
            if (idle > 3 || round > 1000)
            {
                // No wall to slide along, yet no way on: the body overlaps walls it cannot be pushed out of
                // (a gap narrower than the clearance). It stays, and says so.
                return new Result(position, contacts, normal, Stopped: true) { Stuck = true };
            }
        }
    }

    private static Vec2 Project(Vec2 v, Vec2 n) => v - (n * Dot(v, n));

    /// <summary>
    /// How far the body moves along <paramref name="direction"/> (at most <paramref name="length"/>)
    /// before a sub-step ends with the centre within r of an edge; at that sub-step, the distance at
    /// which it first touches (to 1e-10 m).
    /// </summary>
    private static double FreeTravel(List<(Vec2 A, Vec2 B)> edges, Vec2 from, Vec2 direction, double length, double radius)
    {
        if (Clearance(edges, from) < radius - Touch)
        {
            return 0; // starts overlapping: touching at once
        }

        double travelled = 0;
        while (travelled < length)
        {
            Vec2 at = from + (direction * travelled);
            double free = SafeTravel(edges, at, direction, radius);
            if (free >= length - travelled)
            {
                return length;
            }

            if (free >= SubStep)
            {
                travelled += Math.Floor(free / SubStep) * SubStep; // those sub-steps all end clear: skipped at once
                continue;
            }

            double next = Math.Min(travelled + SubStep, length);
            if (Clearance(edges, from + (direction * next)) >= radius - Touch)
            {
                travelled = next;
                continue;
            }

            // A contact within (travelled, next]: halve to its first touch.
            double lo = travelled, hi = next;
            while (hi - lo > 1e-10)
            {
                double mid = 0.5 * (lo + hi);
                if (Clearance(edges, from + (direction * mid)) >= radius - Touch)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            return lo;
        }

        return length;
    }

    /// <summary>
    /// A distance along <paramref name="direction"/> over which no edge can come within r − Touch:
    /// the distance to a segment is convex along a line, so it stays above its tangent there.
    /// </summary>
    private static double SafeTravel(List<(Vec2 A, Vec2 B)> edges, Vec2 p, Vec2 direction, double radius)
    {
        double safe = double.PositiveInfinity;
        foreach ((Vec2 a, Vec2 b) in edges)
        {
            Vec2 away = p - Closest(p, a, b);
            double distance = away.Length;
            if (distance == 0)
            {
                return 0;
            }

            double rate = Dot(direction, away) / distance; // d(distance)/d(travel) here
            if (rate < 0)
            {
                safe = Math.Min(safe, (distance - radius + Touch) / -rate);
            }
        }

        return Math.Max(safe, 0);
    }

    /// <summary>Pushes the centre out to distance r from every edge it is within r of, a few rounds over all of them.</summary>
    private static Vec2 PushOut(List<(Vec2 A, Vec2 B)> edges, Vec2 p, double radius)
    {
        for (int round = 0; round < 8; round++)
        {
            bool pushed = false;
            foreach ((Vec2 a, Vec2 b) in edges)
            {
                Vec2 c = Closest(p, a, b);
                Vec2 away = p - c;
                double distance = away.Length;
                if (distance < radius && distance > 0)
                {
                    p = c + (away * (radius / distance));
                    pushed = true;
                }
            }

            if (!pushed)
            {
                break;
            }
        }

        return p;
    }

    /// <summary>The distinct unit normals (edge → centre) of the edges the centre touches and moves into, the most opposed first.</summary>
    private static List<Vec2> ContactNormals(List<(Vec2 A, Vec2 B)> edges, Vec2 p, Vec2 direction, double radius)
    {
        var normals = new List<Vec2>();
        foreach ((Vec2 a, Vec2 b) in edges)
        {
            Vec2 away = p - Closest(p, a, b);
            double distance = away.Length;
            if (distance > 0 && distance < radius + 1e-7)
            {
                Vec2 n = away / distance;
                if (Dot(direction, n) < -1e-12 && !normals.Any(m => Dot(m, n) > 1 - 1e-9))
                {
                    normals.Add(n);
                }
            }
        }

        normals.Sort((m, n) => Dot(direction, m).CompareTo(Dot(direction, n)));
        return normals;
    }

    private static double Clearance(List<(Vec2 A, Vec2 B)> edges, Vec2 p)
    {
        double best = double.PositiveInfinity;
        foreach ((Vec2 a, Vec2 b) in edges)
        {
            best = Math.Min(best, Distance(p, a, b));
        }

        return best;
    }

    /// <summary>The band-cut edges of walls whose bounds come within <paramref name="reach"/> of <paramref name="centre"/>.</summary>
    private List<(Vec2 A, Vec2 B)> EdgesNear(double zLow, double zHigh, Vec2 centre, double reach)
    {
        var edges = new List<(Vec2, Vec2)>();
        foreach (Wall wall in _walls)
        {
            if (wall.ZMax <= zLow || wall.ZMin >= zHigh
                || wall.MinX > centre.X + reach || wall.MaxX < centre.X - reach || wall.MinY > centre.Y + reach || wall.MaxY < centre.Y - reach)
            {
                continue;
            }

            List<Vec3> band = Cut(Cut(wall.Vertices, zLow, keepAbove: true), zHigh, keepAbove: false);
            for (int i = 0; i < band.Count; i++)
            {
                Vec3 a = band[i], b = band[(i + 1) % band.Count];
                edges.Add((new Vec2(a.X, a.Y), new Vec2(b.X, b.Y)));
            }
        }

        return edges;
    }

    /// <summary>The part of a polygon on one side of the plane z = <paramref name="z"/>.</summary>
    private static List<Vec3> Cut(IReadOnlyList<Vec3> polygon, double z, bool keepAbove)
    {
        var kept = new List<Vec3>();
        for (int i = 0; i < polygon.Count; i++)
        {
            Vec3 p = polygon[i], q = polygon[(i + 1) % polygon.Count];
            double sp = keepAbove ? p.Z - z : z - p.Z, sq = keepAbove ? q.Z - z : z - q.Z;
            if (sp >= 0)
            {
                kept.Add(p);
            }

            if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0))
            {
                double s = sp / (sp - sq);
                kept.Add(new Vec3(p.X + ((q.X - p.X) * s), p.Y + ((q.Y - p.Y) * s), z));
            }
        }

        return kept;
    }

    private static Vec3[] Placed(Frame frame, CellStruct cellStruct, Polygon polygon) =>
        polygon.VertexIds.Select(id => Place(frame, cellStruct.VertexArray.Vertices[(ushort)id].Origin)).ToArray();

    /// <summary>The Newell normal (the winding's, length twice the area).</summary>
    public static Vec3 Newell(IReadOnlyList<Vec3> v)
    {
        double x = 0, y = 0, z = 0;
        for (int i = 0; i < v.Count; i++)
        {
            Vec3 a = v[i], b = v[(i + 1) % v.Count];
            x += (a.Y - b.Y) * (a.Z + b.Z);
            y += (a.Z - b.Z) * (a.X + b.X);
            z += (a.X - b.X) * (a.Y + b.Y);
        }

        return new Vec3(x, y, z);
    }

    /// <summary>Whether <paramref name="polygon"/> lies in the portal's plane with its centroid inside the portal.</summary>
    private static bool Covers(Vec3[] portal, Vec3[] polygon)
    {
        Vec3 n = Newell(portal);
        double length = n.Length;
        if (length == 0)
        {
            return false;
        }

        n = new Vec3(n.X / length, n.Y / length, n.Z / length);
        Vec3 o = portal[0];
        if (polygon.Any(v => Math.Abs((n.X * (v.X - o.X)) + (n.Y * (v.Y - o.Y)) + (n.Z * (v.Z - o.Z))) > CoverTolerance))
        {
            return false;
        }

        // Inside, in the plane: drop the normal's largest axis and test the 2D winding (edges count as inside).
        var c = new Vec3(polygon.Average(v => v.X), polygon.Average(v => v.Y), polygon.Average(v => v.Z));
        Func<Vec3, Vec2> flat = Math.Abs(n.Z) >= Math.Abs(n.X) && Math.Abs(n.Z) >= Math.Abs(n.Y) ? v => new Vec2(v.X, v.Y)
            : Math.Abs(n.X) >= Math.Abs(n.Y) ? v => new Vec2(v.Y, v.Z)
            : v => new Vec2(v.X, v.Z);
        Vec2 point = flat(c);
        int sign = 0;
        for (int i = 0; i < portal.Length; i++)
        {
            Vec2 a = flat(portal[i]), b = flat(portal[(i + 1) % portal.Length]);
            double cross = Cross(b - a, point - a);
            if (Math.Abs(cross) < 1e-9)
            {
                continue;
            }

            int s = Math.Sign(cross);
            if (sign != 0 && s != sign)
            {
                return false;
            }

            sign = s;
        }

        return true;
    }

    /// <summary>The point of segment a–b nearest to <paramref name="p"/>.</summary>
    public static Vec2 Closest(Vec2 p, Vec2 a, Vec2 b)
    {
        Vec2 ab = b - a;
        double l2 = Dot(ab, ab);
        if (l2 == 0)
        {
            return a;
        }

        double u = Math.Clamp(Dot(p - a, ab) / l2, 0, 1);
        return a + (ab * u);
    }

    /// <summary>Distance from <paramref name="p"/> to segment a–b.</summary>
    public static double Distance(Vec2 p, Vec2 a, Vec2 b) => (p - Closest(p, a, b)).Length;

    private static bool SegmentsMeet(Vec2 p, Vec2 q, Vec2 a, Vec2 b)
    {
        double d1 = Cross(q - p, a - p), d2 = Cross(q - p, b - p), d3 = Cross(b - a, p - a), d4 = Cross(b - a, q - a);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        {
            return true;
        }

        return Distance(a, p, q) == 0 || Distance(b, p, q) == 0 || Distance(p, a, b) == 0 || Distance(q, a, b) == 0;
    }

    private static double Dot(Vec2 a, Vec2 b) => (a.X * b.X) + (a.Y * b.Y);

    private static double Cross(Vec2 a, Vec2 b) => (a.X * b.Y) - (a.Y * b.X);

    /// <summary>Where a move ended: the centre, how many walls it touched, the last one's normal (towards the body), and whether a corner, the contact limit or a gap too narrow stopped it.</summary>
    public readonly record struct Result(Vec2 End, int Contacts, Vec2 Normal, bool Stopped)
    {
        /// <summary>The body could not be placed clear of the walls (it overlaps walls closer together than its clearance).</summary>
        public bool Stuck { get; init; }
    }

    /// <summary>A 2D point or vector, double precision.</summary>
    public readonly record struct Vec2(double X, double Y)
    {
        public double Length => Math.Sqrt((X * X) + (Y * Y));

        public static Vec2 operator +(Vec2 a, Vec2 b) => new(a.X + b.X, a.Y + b.Y);

        public static Vec2 operator -(Vec2 a, Vec2 b) => new(a.X - b.X, a.Y - b.Y);

        public static Vec2 operator *(Vec2 a, double s) => new(a.X * s, a.Y * s);

        public static Vec2 operator /(Vec2 a, double s) => new(a.X / s, a.Y / s);

        public override string ToString() => FormattableString.Invariant($"({X:R}, {Y:R})");
    }

    /// <summary>A 3D point, double precision.</summary>
    public readonly record struct Vec3(double X, double Y, double Z)
    {
        public double Length => Math.Sqrt((X * X) + (Y * Y) + (Z * Z));
    }

    private sealed class Wall
    {
        public Wall(Vec3[] vertices)
        {
            Vertices = vertices;
            ZMin = vertices.Min(v => v.Z);
            ZMax = vertices.Max(v => v.Z);
            MinX = vertices.Min(v => v.X);
            MaxX = vertices.Max(v => v.X);
            MinY = vertices.Min(v => v.Y);
            MaxY = vertices.Max(v => v.Y);
        }

        public Vec3[] Vertices { get; }

        public double ZMin { get; }

        public double ZMax { get; }

        public double MinX { get; }

        public double MaxX { get; }

        public double MinY { get; }

        public double MaxY { get; }
    }
}
