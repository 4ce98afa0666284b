using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced): the cast's slow reference.

/// <summary>
/// A slow, double-precision reference of a cast (a sphere of radius r swept along a segment; r = 0 is a ray), written
/// from the geometric definition, not from the engine's code: the contact is the first fraction t in 0..1 at which the
/// distance from the centre P(t) = from + t·(to − from) to a shape falls to r.
/// </summary>
/// <remarks>
/// <para>
/// Shapes are closed sets in double precision: convex planar polygons (a triangle is one; the distance to a polygon is
/// the distance to its plane where the foot of the perpendicular lies inside it, else to the nearest of its edges), solid
/// upright cylinders (the exact distance to the solid), and the game's terrain as its triangles. Each shape's first
/// contact is found on its own and the earliest one wins; the first contact with the union is the earliest of the
/// shapes' first contacts.
/// </para>
/// <para>
/// A shape's first contact is found by advancing along the segment by the shape's distance less r (a distance never
/// lets the centre pass the shape: nothing comes nearer than that within that travel). A ray stops within
/// <see cref="RayTouch"/> of the shape. A sphere advances at least <see cref="MinStep"/>; a step that ends overlapping
/// is bisected back to the first touch (to 1e-12 m of travel), and one that comes within <see cref="Touch"/> and draws
/// away again is a graze at its nearest. A dip into a shape shallower than a step of <see cref="MinStep"/> can see
/// (below 1e-13 m deep for r ≥ 1 cm) is the only thing it may miss.
/// </para>
/// <para>
/// Coordinates are a frame of the caller's choosing (the tests use one landblock's local metres). The answer names the
/// shape met first and every shape within <see cref="TieTolerance"/> of touching the sphere there (two polygons sharing
/// an edge, a floor on the terrain), so a test can accept any of them, and the normals the contact may have.
/// </para>
/// </remarks>
internal sealed class CastReference
{
    /// <summary>A sphere within this of a shape (metres) and drawing away grazes it.</summary>
    public const double Touch = 1e-10;

    /// <summary>A ray within this of a shape (metres) meets it (a ray's distance never goes below 0: no overlap to halve back from).</summary>
    public const double RayTouch = 1e-12;

    /// <summary>The least advance of a sphere (metres of travel) while it closes on a shape.</summary>
    public const double MinStep = 1e-7;

    /// <summary>Shapes within this (metres) of touching the sphere at the contact are met together with the first; a ray's contact within this of a cylinder's rim may have the side's or the cap's normal.</summary>
    public const double TieTolerance = 1e-5;

    /// <summary>The game's walkable limit: a polygon whose unit normal Z is at least this is a floor.</summary>
    public const double FloorZ = 0.66417414618662751;

    private const long MaxSteps = 50_000_000;

    private readonly List<Shape> _shapes;

    public CastReference(IEnumerable<Shape> shapes)
    {
        _shapes = [.. shapes];
    }

    public IReadOnlyList<Shape> Shapes => _shapes;

    /// <summary>
    /// The first contact of a sphere of <paramref name="radius"/> swept from <paramref name="from"/> to
    /// <paramref name="to"/>, or null when it meets nothing. A start already within the radius of a shape is a contact at
    /// 0 with <see cref="Hit.Overlapping"/> set.
    /// </summary>
    public Hit? Cast(V3 from, V3 to, double radius)
    {
        V3 move = to - from;
        double length = move.Length;
        (Shape Shape, double T)? best = null;
        foreach (Shape shape in _shapes)
        {
            if (!shape.MayMeet(from, to, radius))
            {
                continue;
            }

            double? t = FirstTouch(shape, from, move, length, radius);
            if (t is double value)
            {
                if (best is null || value < best.Value.T)
                {
                    best = (shape, value);
                }
            }
        }

        if (best is not (Shape first, double tFirst))
        {
            return null;
        }

        V3 centre = from + (move * tFirst);
        V3 point = first.Closest(centre);
        List<Shape> together = [.. _shapes.Where(s => s.MayMeet(centre, centre, radius + TieTolerance) && s.Distance(centre) <= radius + TieTolerance)];
        var normals = new List<V3>();
        foreach (Shape s in together)
        {
            V3 away = centre - s.Closest(centre);
            double gap = away.Length;
            if (radius > 0 && gap > 0)
            {
                normals.Add(away * (1.0 / gap));
            }
            else
            {
                normals.AddRange(s.Normals(s.Closest(centre), from - centre));
            }
        }

        return new Hit(tFirst, centre, point, normals, first, together, Overlapping: tFirst == 0 && first.Distance(from) <= radius + (radius > 0 ? Touch : RayTouch));
    }

    /// <summary>
    /// The first fraction at which the sphere touches <paramref name="shape"/>; null for none. A ray (r = 0) is advanced
    /// until it is within <see cref="RayTouch"/> of the shape; a sphere until a step ends overlapping it (then halved
    /// back to the first touch) or it comes within <see cref="Touch"/> and moves away again (a graze).
    /// </summary>
    private static double? FirstTouch(Shape shape, V3 from, V3 move, double length, double radius)
    {
        double Gap(double t) => shape.Distance(from + (move * t)) - radius;

        double t = 0;
        double gap = Gap(0);
        if (gap <= (radius > 0 ? Touch : RayTouch))
        {
            return 0;
        }

        if (length == 0)
        {
            return null;
        }

        for (long step = 0; step < MaxSteps; step++)
        {
            double advance = radius > 0 ? Math.Max(gap, MinStep) : gap;
            double next = Math.Min(t + (advance / length), 1.0);
            double g = Gap(next);
            if (g < 0)
            {
                // Only a step of the least length can end overlapping: halve back to the first touch.
                double lo = t, hi = next;
                while ((hi - lo) * length > 1e-12)
                {
                    double mid = 0.5 * (lo + hi);
                    if (Gap(mid) < 0)
                    {
                        hi = mid;
                    }
                    else
                    {
                        lo = mid;
                    }
                }

                return lo;
            }

            if (radius == 0 && g <= RayTouch)
            {
                return next;
            }

            if (radius > 0 && gap <= Touch && g >= gap)
            {
                return t; // it came within a touch and draws away: a graze
            }

            if (next >= 1.0)
            {
                return g <= Touch ? 1.0 : null;
            }

            (t, gap) = (next, g);
        }

        throw new InvalidOperationException($"the reference did not settle on {shape.Name} within {MaxSteps} steps (a path closing on it ever more slowly)");
    }

    /// <summary>
    /// The contact: the fraction, the centre, the point of the shape nearest the centre, the shape met first and every
    /// shape within <see cref="TieTolerance"/> of touching there (<see cref="Together"/>), and the normals the contact
    /// may have: from each of those shapes' nearest points to the centre, or, for a ray on a shape, that shape's face
    /// normals facing the start (one on a face; both faces' at an edge between two; the side's and the cap's at a
    /// cylinder's rim).
    /// </summary>
    public sealed record Hit(double T, V3 Centre, V3 Point, IReadOnlyList<V3> Normals, Shape Shape, IReadOnlyList<Shape> Together, bool Overlapping)
    {
        public override string ToString() =>
            FormattableString.Invariant($"t {T:R} centre {Centre} point {Point} normals [{string.Join(", ", Normals)}] on {Shape.Name} (touching: {string.Join(", ", Together.Select(s => s.Name))})");
    }

    /// <summary>A closed set in space, with what the engine is expected to name it.</summary>
    public abstract class Shape(SurfaceKind kind, uint id, string name)
    {
        public SurfaceKind Kind { get; } = kind;

        public uint Id { get; } = id;

        public string Name { get; } = name;

        /// <summary>The point of the shape nearest <paramref name="p"/> (<paramref name="p"/> itself inside a solid).</summary>
        public abstract V3 Closest(V3 p);

        public double Distance(V3 p) => (p - Closest(p)).Length;

        /// <summary>The bounds of the shape.</summary>
        public abstract (V3 Min, V3 Max) Bounds { get; }

        /// <summary>The unit normals of the faces at <paramref name="point"/> (a point of the shape), each on the side of <paramref name="towards"/>.</summary>
        public abstract IEnumerable<V3> Normals(V3 point, V3 towards);

        /// <summary>Whether the sphere's path comes within reach of the bounds at all (a test that never excludes a contact).</summary>
        public bool MayMeet(V3 from, V3 to, double radius)
        {
            (V3 lo, V3 hi) = Bounds;
            double grow = radius + 1e-6;
            return Math.Min(from.X, to.X) <= hi.X + grow && Math.Max(from.X, to.X) >= lo.X - grow
                && Math.Min(from.Y, to.Y) <= hi.Y + grow && Math.Max(from.Y, to.Y) >= lo.Y - grow
                && Math.Min(from.Z, to.Z) <= hi.Z + grow && Math.Max(from.Z, to.Z) >= lo.Z - grow;
        }
    }

    /// <summary>A convex planar polygon (any winding), two-sided, closed: its face, edges and corners.</summary>
    public sealed class Polygon : Shape
    {
        private readonly V3[] _v;
        private readonly V3 _n;
        private readonly V3 _centre;

        public Polygon(IReadOnlyList<V3> vertices, SurfaceKind kind, uint id, string name)
            : base(kind, id, name)
        {
            _v = [.. vertices];
            _n = UnitNormal(_v);
            _centre = Mean(_v);
            Bounds = (new V3(_v.Min(v => v.X), _v.Min(v => v.Y), _v.Min(v => v.Z)), new V3(_v.Max(v => v.X), _v.Max(v => v.Y), _v.Max(v => v.Z)));
        }

        public IReadOnlyList<V3> Vertices => _v;

        /// <summary>The unit normal of the winding.</summary>
        public V3 Normal => _n;

        public override (V3 Min, V3 Max) Bounds { get; }

        public override V3 Closest(V3 p)
        {
            // The foot of the perpendicular on the plane, if it lies inside: the polygon's nearest point.
            V3 foot = p - (_n * V3.Dot(p - _centre, _n));
            if (Inside(foot))
            {
                return foot;
            }

            // Else the nearest point of its outline.
            V3 best = _v[0];
            double bestDistance = double.PositiveInfinity;
            for (int i = 0, j = _v.Length - 1; i < _v.Length; j = i++)
            {
                V3 c = OnSegment(p, _v[j], _v[i]);
                double d = (p - c).Length;
                if (d < bestDistance)
                {
                    (best, bestDistance) = (c, d);
                }
            }

            return best;
        }

        public override IEnumerable<V3> Normals(V3 point, V3 towards)
        {
            yield return V3.Dot(_n, towards) >= 0 ? _n : -_n; // two-sided: the face towards the start
        }

        /// <summary>Whether <paramref name="p"/> (on the plane) is inside the polygon or on its outline.</summary>
        private bool Inside(V3 p)
        {
            for (int i = 0, j = _v.Length - 1; i < _v.Length; j = i++)
            {
                V3 e = _v[i] - _v[j];
                double el = e.Length;
                if (el == 0)
                {
                    continue;
                }

                // The inward side of the edge is to the left of it seen down the winding's normal.
                if (V3.Dot(V3.Cross(e, p - _v[j]), _n) / el < 0)
                {
                    return false;
                }
            }

            return true;
        }
    }

    /// <summary>A solid upright cylinder: axis (X, Y), radius, from Z0 up to Z1.</summary>
    public sealed class Cylinder(double x, double y, double radius, double z0, double z1, SurfaceKind kind, uint id, string name) : Shape(kind, id, name)
    {
        public override (V3 Min, V3 Max) Bounds { get; } = (new V3(x - radius, y - radius, z0), new V3(x + radius, y + radius, z1));

        public override V3 Closest(V3 p)
        {
            double dx = p.X - x, dy = p.Y - y, rho = Math.Sqrt((dx * dx) + (dy * dy));
            double k = rho > radius ? radius / rho : 1.0; // pulled in to the side when outside it
            return new V3(x + (dx * k), y + (dy * k), Math.Clamp(p.Z, z0, z1));
        }

        public override IEnumerable<V3> Normals(V3 point, V3 towards)
        {
            // Within TieTolerance of the rim, both the side's and the cap's (a ray there may be met by either).
            double dx = point.X - x, dy = point.Y - y, rho = Math.Sqrt((dx * dx) + (dy * dy));
            if (Math.Abs(rho - radius) < TieTolerance && rho > 0)
            {
                yield return new V3(dx / rho, dy / rho, 0); // the side
            }

            if (Math.Abs(point.Z - z0) < TieTolerance || Math.Abs(point.Z - z1) < TieTolerance)
            {
                yield return new V3(0, 0, towards.Z >= 0 ? 1 : -1); // a cap
            }
        }
    }

    /// <summary>A point or a vector, double precision, metres.</summary>
    public readonly record struct V3(double X, double Y, double Z)
    {
        public double Length => Math.Sqrt(Dot(this, this));

        public static V3 operator +(V3 a, V3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        public static V3 operator -(V3 a, V3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

        public static V3 operator -(V3 a) => new(-a.X, -a.Y, -a.Z);

        public static V3 operator *(V3 a, double s) => new(a.X * s, a.Y * s, a.Z * s);

        public static double Dot(V3 a, V3 b) => (a.X * b.X) + (a.Y * b.Y) + (a.Z * b.Z);

        public static V3 Cross(V3 a, V3 b) => new((a.Y * b.Z) - (a.Z * b.Y), (a.Z * b.X) - (a.X * b.Z), (a.X * b.Y) - (a.Y * b.X));

        public static V3 Of(Vector3 v) => new(v.X, v.Y, v.Z);

        public static V3 Of(ReferenceBody.Vec3 v) => new(v.X, v.Y, v.Z);

        public override string ToString() => FormattableString.Invariant($"({X:F7}, {Y:F7}, {Z:F7})");
    }

    /// <summary>The point of segment a–b nearest <paramref name="p"/>.</summary>
    public static V3 OnSegment(V3 p, V3 a, V3 b)
    {
        V3 ab = b - a;
        double l2 = V3.Dot(ab, ab);
        double s = l2 == 0 ? 0 : Math.Clamp(V3.Dot(p - a, ab) / l2, 0, 1);
        return a + (ab * s);
    }

    /// <summary>The unit normal of a polygon's winding (Newell's sum); zero for no area.</summary>
    public static V3 UnitNormal(IReadOnlyList<V3> v)
    {
        ReferenceBody.Vec3 n = ReferenceBody.Newell([.. v.Select(p => new ReferenceBody.Vec3(p.X, p.Y, p.Z))]);
        double l = Math.Sqrt((n.X * n.X) + (n.Y * n.Y) + (n.Z * n.Z));
        return l == 0 ? default : new V3(n.X / l, n.Y / l, n.Z / l);
    }

    private static V3 Mean(IReadOnlyList<V3> v) => new(v.Average(p => p.X), v.Average(p => p.Y), v.Average(p => p.Z));

    // ---- The world's shapes, built from their definitions ----

    /// <summary>Whether the game splits global terrain cell (gx, gy) along its SW–NE diagonal: the top bit of the game's hash of the cell (32-bit wrap-around).</summary>
    public static bool SplitsSwToNe(long gx, long gy)
    {
        ulong x = (ulong)gx, y = (ulong)gy;
        ulong hash = ((x * y * 0x0CCAC033UL) - (x * 0x421BE3BDUL) + (y * 0x6C1AC587UL) - 0x519B8F25UL) & 0xFFFF_FFFFUL;
        return (hash & 0x8000_0000UL) != 0;
    }

    /// <summary>
    /// The game's terrain of landblock (<paramref name="landblockX"/>, <paramref name="landblockY"/>): in each 24 m cell
    /// two flat triangles through its corners' heights, split SW–NE (triangles SW–SE–NE and SW–NE–NW) or SE–NW (SW–SE–NW
    /// and NE–NW–SE) by <see cref="SplitsSwToNe"/>; placed with the landblock's south-west corner at
    /// <paramref name="corner"/>. Each triangle is named by its outdoor cell.
    /// </summary>
    /// <param name="metres">The 81 vertex heights, metres, x-major (vertex (x, y) at [x·9 + y]).</param>
    public static IEnumerable<Shape> Terrain(IReadOnlyList<double> metres, int landblockX, int landblockY, V3 corner)
    {
        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                V3 At(int i, int j) => new(corner.X + (24.0 * (cx + i)), corner.Y + (24.0 * (cy + j)), corner.Z + metres[((cx + i) * 9) + cy + j]);
                V3 sw = At(0, 0), se = At(1, 0), nw = At(0, 1), ne = At(1, 1);
                uint id = ((uint)landblockX << 24) | ((uint)landblockY << 16) | (uint)((cx * 8) + cy + 1);
                string name = FormattableString.Invariant($"terrain 0x{id:X8}");
                if (SplitsSwToNe((landblockX * 8) + cx, (landblockY * 8) + cy))
                {
                    yield return new Polygon([sw, se, ne], SurfaceKind.Terrain, id, name + " SE");
                    yield return new Polygon([sw, ne, nw], SurfaceKind.Terrain, id, name + " NW");
                }
                else
                {
                    yield return new Polygon([sw, se, nw], SurfaceKind.Terrain, id, name + " SW");
                    yield return new Polygon([ne, nw, se], SurfaceKind.Terrain, id, name + " NE");
                }
            }
        }
    }

    /// <summary>
    /// A cell's physics polygons placed in double precision (<see cref="ReferenceBody.Place"/>), moved by
    /// <paramref name="offset"/>: its floors (unit normal Z ≥ <see cref="FloorZ"/>) as floors, its walls as
    /// <see cref="ReferenceBody.WallsOf"/> gives them (a doorway's cover left out), those facing down (normal Z ≤
    /// −<see cref="FloorZ"/>) named ceilings.
    /// </summary>
    public static IEnumerable<Shape> Cell(uint cellId, EnvCell cell, CellStruct cellStruct, V3 offset = default)
    {
        string name = FormattableString.Invariant($"cell 0x{cellId:X8}");
        foreach (AcDream.Core.Dat.Polygon polygon in cellStruct.PhysicsPolygons.OrderBy(p => p.Key).Select(p => p.Value))
        {
            V3[] v = [.. polygon.VertexIds.Select(i => V3.Of(ReferenceBody.Place(cell.Position, cellStruct.VertexArray.Vertices[(ushort)i].Origin)) + offset)];
            if (UnitNormal(v).Z >= FloorZ)
            {
                yield return new Polygon(v, SurfaceKind.CellFloor, cellId, name + " floor");
            }
        }

        foreach (ReferenceBody.Vec3[] wall in ReferenceBody.WallsOf(cell, cellStruct))
        {
            V3[] v = [.. wall.Select(p => V3.Of(p) + offset)];
            bool ceiling = UnitNormal(v).Z <= -FloorZ;
            yield return new Polygon(v, ceiling ? SurfaceKind.CellCeiling : SurfaceKind.CellWall, cellId, name + (ceiling ? " ceiling" : " wall"));
        }
    }

    /// <summary>
    /// The portals of <paramref name="cells"/> that lead to a cell not among them (nor the outdoors), each its polygon
    /// placed in double precision: a cast stops at such a portal as at a wall of the cell that holds it.
    /// </summary>
    public static IEnumerable<Shape> MissingPortals(IReadOnlyList<(uint Id, EnvCell Cell, CellStruct Struct)> cells)
    {
        var ids = cells.Select(c => c.Id).ToHashSet();
        foreach ((uint id, EnvCell cell, CellStruct cellStruct) in cells.OrderBy(c => c.Id))
        {
            foreach (CellPortal portal in cell.CellPortals)
            {
                if (portal.OtherCellId == 0xFFFF || ids.Contains((id & 0xFFFF0000u) | portal.OtherCellId))
                {
                    continue;
                }

                V3[] polygon = [.. cellStruct.Polygons[portal.PolygonId].VertexIds
                    .Select(i => V3.Of(ReferenceBody.Place(cell.Position, cellStruct.VertexArray.Vertices[(ushort)i].Origin)))];
                yield return new Polygon(polygon, SurfaceKind.CellWall, id, FormattableString.Invariant($"cell 0x{id:X8} portal to missing 0x{portal.OtherCellId:X4}"));
            }
        }
    }

    /// <summary>
    /// A GfxObj's physics polygons placed by <paramref name="frame"/> in double precision, moved by
    /// <paramref name="offset"/>: floors as <see cref="SurfaceKind.ObjectFloor"/>, the rest as <paramref name="wallKind"/>
    /// (a building's shell, an object's wall, a mover); <paramref name="floors"/> false leaves the floors out (a mover has
    /// only walls).
    /// </summary>
    public static IEnumerable<Shape> Model(GfxObj gfxObj, Frame frame, SurfaceKind wallKind, uint id, V3 offset = default, bool floors = true)
    {
        string name = FormattableString.Invariant($"{wallKind} 0x{id:X8}");
        foreach (AcDream.Core.Dat.Polygon polygon in gfxObj.PhysicsPolygons.OrderBy(p => p.Key).Select(p => p.Value))
        {
            V3[] v = [.. polygon.VertexIds.Select(i => V3.Of(ReferenceBody.Place(frame, gfxObj.VertexArray.Vertices[(ushort)i].Origin)) + offset)];
            V3 n = UnitNormal(v);
            if (n == default)
            {
                continue;
            }

            bool floor = n.Z >= FloorZ;
            if (floor && !floors)
            {
                continue;
            }

            yield return new Polygon(v, floor ? SurfaceKind.ObjectFloor : wallKind, id, name + (floor ? " floor" : " wall"));
        }
    }
}
