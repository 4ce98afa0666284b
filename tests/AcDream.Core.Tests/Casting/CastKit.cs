using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Testing;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// An engine and the same world as <see cref="CastReference"/> shapes, in the landblock-local metres of
/// <see cref="Landblock"/>; and the comparison of a cast with the reference.
/// </summary>
/// <remarks>
/// A cast is given world floats; the reference is given exactly those floats less the landblock's world origin
/// (<see cref="Local(Vector3)"/>, exact in double), so both sweep the same segment. The engine's world answers are
/// floats: in the global frame they are rounded to 2–4 mm (Holtburg's world X is 32,448 m, its Y 34,560 m), so there
/// positions are compared within 1e-4 m plus half the float spacing of the world coordinate, and the travel to the
/// contact (<see cref="CastHit.Fraction"/> × the segment's length) within 1e-4 m, which rounding does not touch.
/// </remarks>
internal sealed class CastScene(PhysicsEngine engine, string frame, uint landblock, IEnumerable<Shape> shapes)
{
    /// <summary>The largest difference from the reference a contact may have, metres.</summary>
    public const double Tolerance = 1e-4;

    /// <summary>Unit normals agree within this (a sphere's normal is its centre less its contact point over its radius).</summary>
    public const double NormalTolerance = 1e-3;

    private CastReference? _reference;

    public PhysicsEngine Engine { get; } = engine;

    public string Frame { get; } = frame;

    public uint Landblock { get; } = landblock;

    public List<Shape> Shapes { get; } = [.. shapes];

    public CastReference Reference => _reference ??= new CastReference(Shapes);

    public Vector3 Origin => Engine.GetLandblockOrigin(Landblock);

    public bool Global => Frame == "global";

    /// <summary>
    /// How far (metres) the engine's copy of the shapes may lie from the reference's: 0 for geometry whose coordinates
    /// are floats exactly (the terrain, rooms built at whole and half metres); for the real cells and objects, which the
    /// engine places in floats and the reference in double, the rounding of a coordinate near 100–200 m (7.6e-6 m) and
    /// the dat rotations' noise, 1e-5 m. A surface that far off moves a contact along the path by that over the sine of
    /// the angle the path meets it at, which <see cref="Agree"/> allows on top of <see cref="Tolerance"/>.
    /// </summary>
    public double GeometryRounding { get; init; }

    /// <summary>A reference-frame point in world floats (rounded once).</summary>
    public Vector3 World(V3 local)
    {
        Vector3 o = Origin;
        return new Vector3((float)(o.X + local.X), (float)(o.Y + local.Y), (float)(o.Z + local.Z));
    }

    public Vector3 World(double x, double y, double z) => World(new V3(x, y, z));

    /// <summary>A world float point in the reference frame, exactly.</summary>
    public V3 Local(Vector3 world)
    {
        Vector3 o = Origin;
        return new V3((double)world.X - o.X, (double)world.Y - o.Y, (double)world.Z - o.Z);
    }

    /// <summary>The reference's contact for the segment the engine is given.</summary>
    public Hit? Expected(Vector3 from, Vector3 to, float radius) => Reference.Cast(Local(from), Local(to), radius);

    /// <summary>The highest surface of the reference's shapes under (x, y) between z −5,000 and 5,000 m (a ray down).</summary>
    public double Ground(double x, double y) =>
        Reference.Cast(new V3(x, y, 5000), new V3(x, y, -5000), 0) is Hit hit ? hit.Point.Z : double.NaN;

    /// <summary>The distance from <paramref name="p"/> to the nearest reference shape.</summary>
    public double Clearance(V3 p) => Shapes.Count == 0 ? double.PositiveInfinity : Shapes.Min(s => s.Distance(p));

    /// <summary>
    /// Casts and checks the answer against the reference: no contact, or the same contact (travel, centre, point within
    /// <see cref="Tolerance"/>; normal within <see cref="NormalTolerance"/> of one the contact may have; a shape touching there named).
    /// Every value is in the failure message; the deviations go to <paramref name="worst"/>.
    /// </summary>
    public CastHit Check(Vector3 from, uint cellId, Vector3 to, float radius, Deviations worst, string what, CastFilter filter = CastFilter.None, uint ignoreId = 0)
    {
        CastHit hit = Engine.Cast(from, cellId, to, new CastOptions(radius, filter), ignoreId);
        Hit? expected = Expected(from, to, radius);
        Agree(hit, expected, from, to, radius, worst, what);
        return hit;
    }

    /// <summary>Checks <paramref name="hit"/> against <paramref name="expected"/> (see <see cref="Check"/>).</summary>
    public void Agree(CastHit hit, Hit? expected, Vector3 from, Vector3 to, float radius, Deviations worst, string what)
    {
        to = from + (to - from); // the end the engine casts to: its start plus its delta, in floats
        V3 a = Local(from), b = Local(to);
        double length = (b - a).Length;
        string says = $"{what} [{Frame}]: from {a} to {b} (world {from} → {to}), radius {radius}; engine {hit} (centre {Local(hit.Position)}, point {Local(hit.Point)}); reference {expected?.ToString() ?? "no contact"}";
        if (expected is null)
        {
            hit.Hit.Should().BeFalse($"the reference meets nothing: {says}");
            hit.Fraction.Should().Be(1f, says);
            hit.Position.Should().Be(to, says);
            worst.Misses++;
            return;
        }

        expected.Overlapping.Should().BeFalse($"a test's start must be clear of every shape: {says}");
        hit.Hit.Should().BeTrue($"the reference meets {expected.Shape.Name}: {says}");
        expected.Normals.Should().NotBeEmpty(says);
        V3 n = expected.Normals.MinBy(n => (V3.Of(hit.Normal) - n).Length);
        double normal = (V3.Of(hit.Normal) - n).Length;
        double approach = Math.Abs(V3.Dot(n, (b - a) * (1.0 / length))); // the sine of the angle the path meets the surface at
        double allowance = GeometryRounding / Math.Max(approach, 1e-9);
        double travel = Math.Abs(((double)hit.Fraction - expected.T) * length);
        double centre = (Local(hit.Position) - expected.Centre).Length;
        double point = (Local(hit.Point) - expected.Point).Length;
        double rounding = Global ? Math.Max(HalfSpacing(hit.Position), HalfSpacing(hit.Point)) : 0;
        string allowed = allowance > 0 ? FormattableString.Invariant($" (with {allowance:E2} m for the geometry's float vertices at an approach of {approach:F4})") : "";
        travel.Should().BeLessThanOrEqualTo(Tolerance + allowance, $"the travel to the contact{allowed}: {says}");
        centre.Should().BeLessThanOrEqualTo(Tolerance + allowance + rounding, $"the centre at the contact{allowed}: {says}");
        point.Should().BeLessThanOrEqualTo(Tolerance + allowance + rounding, $"the contact point{allowed}: {says}");
        normal.Should().BeLessThanOrEqualTo(NormalTolerance, $"the normal (one of the reference's there): {says}");

        expected.Together.Should().Contain(s => s.Kind == hit.Kind && s.Id == hit.Id, $"the engine names a shape met there ({hit.Kind} 0x{hit.Id:X8}): {says}");
        worst.Add(travel, Global ? 0 : centre, Global ? 0 : point, normal);
    }

    /// <summary>
    /// As <see cref="Agree"/>, but a disagreement is recorded in <paramref name="worst"/> (its message kept) rather than
    /// thrown, so a test over many random casts reports every kind of disagreement it finds, not only the first.
    /// </summary>
    public void Tally(CastHit hit, Hit? expected, Vector3 from, Vector3 to, float radius, Deviations worst, string what)
    {
        try
        {
            Agree(hit, expected, from, to, radius, worst, what);
        }
        catch (Xunit.Sdk.XunitException e)
        {
            worst.Fail(e.Message);
        }
    }

    /// <summary>Half the float spacing of a world point's largest coordinate, metres: what rounding it to floats may move it by on each axis, as a length.</summary>
    public static double HalfSpacing(Vector3 p)
    {
        static double Half(float v) => (MathF.BitIncrement(MathF.Abs(v)) - MathF.Abs(v)) / 2.0;
        return Math.Sqrt((Half(p.X) * Half(p.X)) + (Half(p.Y) * Half(p.Y)) + (Half(p.Z) * Half(p.Z)));
    }
}

/// <summary>The worst deviations from the reference seen by a test (metres), and how many casts it compared.</summary>
internal sealed class Deviations(string frame)
{
    public double Travel { get; private set; }

    public double Centre { get; private set; }

    public double Point { get; private set; }

    public double Normal { get; private set; }

    public int Hits { get; private set; }

    public int Misses { get; set; }

    /// <summary>The disagreements recorded by <see cref="CastScene.Tally"/>.</summary>
    public List<string> Failures { get; } = [];

    public void Fail(string message) => Failures.Add(message);

    /// <summary>How many disagreements, how many of them with each shape the reference met first, and the first of each in full.</summary>
    public string FailureReport()
    {
        string nl = System.Environment.NewLine;
        var groups = Failures
            .GroupBy(f => f.Contains(" on ", StringComparison.Ordinal) ? f[(f.LastIndexOf(" on ", StringComparison.Ordinal) + 4)..].Split(" (")[0] : "no contact")
            .ToList();
        return $"{Failures.Count} disagreements with the reference ({string.Join("; ", groups.Select(g => $"{g.Count()} where the reference met {g.Key}"))}); the first of each:{nl}{string.Join(nl + nl, groups.Take(6).Select(g => g.First()))}";
    }

    public void Add(double travel, double centre, double point, double normal)
    {
        Travel = Math.Max(Travel, travel);
        Centre = Math.Max(Centre, centre);
        Point = Math.Max(Point, point);
        Normal = Math.Max(Normal, normal);
        Hits++;
    }

    public override string ToString() => frame == "global"
        ? FormattableString.Invariant($"[global] {Hits} contacts and {Misses} misses compared; worst |engine − reference|: travel {Travel:E2} m, normal {Normal:E2} (positions rounded to the world's float spacing)")
        : FormattableString.Invariant($"[centred] {Hits} contacts and {Misses} misses compared; worst |engine − reference|: travel {Travel:E2} m, centre {Centre:E2} m, point {Point:E2} m, normal {Normal:E2}");
}

/// <summary>The worlds the cast tests use, each with its reference shapes.</summary>
internal static class CastWorlds
{
    public const uint South = 0xA9B3FFFFu;

    /// <summary>The <see cref="CastScene.GeometryRounding"/> of the real cells and objects, metres.</summary>
    public const double RealGeometry = 1e-5;

    public static TheoryData<string> Frames() => new() { "centred", "global" };

    public static PhysicsEngine NewEngine(string frame) => frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);

    /// <summary>
    /// <see cref="HoltburgCells.OnHills"/> with a seed, and its terrain as the reference has it: the heights read back at
    /// the vertices (exact: a vertex's height is one table entry), and the flat south neighbour.
    /// </summary>
    public static (CastScene Scene, TerrainSurface Terrain) Hills(int seed, string frame)
    {
        (PhysicsEngine engine, TerrainSurface terrain) = HoltburgCells.OnHills(new Random(seed), frame);
        var shapes = new List<Shape>();
        shapes.AddRange(Terrain(VertexHeights(terrain), TestData.Holtburg, default));
        shapes.AddRange(Terrain(Flat(94f), South, new V3(0, -192, 0)));
        return (new CastScene(engine, frame, TestData.Holtburg, shapes), terrain);
    }

    /// <summary>
    /// Rolling hills over the 3 × 3 landblocks around Holtburg (0xA8B3..0xAAB5), seamless: each vertex's height index is
    /// one function of its global vertex coordinates (two long waves and a seeded ripple of ±3), so neighbours share
    /// their seam heights; the linear table (2 m an index), about 30–130 m. The reference holds all 1,152 triangles.
    /// </summary>
    public static CastScene Rolling(int seed, string frame)
    {
        PhysicsEngine engine = NewEngine(frame);
        float[] table = TestData.LinearTable();
        double phaseX = seed * 0.37, phaseY = seed * 0.91;
        int Index(int gx, int gy)
        {
            uint hash = unchecked(((uint)gx * 73856093u) ^ ((uint)gy * 19349663u) ^ ((uint)seed * 83492791u));
            hash = unchecked((hash ^ (hash >> 13)) * 0x5BD1E995u);
            int ripple = (int)((hash >> 8) % 7) - 3;
            return 40 + (int)Math.Round((12 * Math.Sin((gx * 0.45) + phaseX)) + (9 * Math.Cos((gy * 0.6) + phaseY))) + ripple;
        }

        var shapes = new List<Shape>();
        for (int lx = 0xA8; lx <= 0xAA; lx++)
        {
            for (int ly = 0xB3; ly <= 0xB5; ly++)
            {
                uint id = ((uint)lx << 24) | ((uint)ly << 16) | 0xFFFF;
                byte[] heights = TestData.Heights((x, y) => Index((lx * 8) + x, (ly * 8) + y));
                engine.AddLandblock(id, new TerrainSurface(heights, table, id), []);
                double[] metres = [.. heights.Select(h => (double)table[h])];
                shapes.AddRange(Terrain(metres, id, new V3((lx - 0xA9) * 192.0, (ly - 0xB4) * 192.0, 0)));
            }
        }

        return new CastScene(engine, frame, TestData.Holtburg, shapes);
    }

    /// <summary>The 81 vertex heights of a terrain, metres, x-major.</summary>
    public static double[] VertexHeights(TerrainSurface terrain)
    {
        var heights = new double[81];
        for (int x = 0; x < 9; x++)
        {
            for (int y = 0; y < 9; y++)
            {
                heights[(x * 9) + y] = terrain.SampleZ(24f * x, 24f * y);
            }
        }

        return heights;
    }

    public static double[] Flat(float z) => Enumerable.Repeat((double)z, 81).ToArray();

    /// <summary>The game's terrain triangles of a landblock whose south-west corner is at <paramref name="corner"/>.</summary>
    public static IEnumerable<Shape> Terrain(double[] heights, uint landblockId, V3 corner) =>
        CastReference.Terrain(heights, (int)(landblockId >> 24), (int)((landblockId >> 16) & 0xFF), corner);

    /// <summary>Every physics polygon of the 22 real Holtburg cells (see <see cref="CastReference.Cell"/>).</summary>
    public static IEnumerable<Shape> HoltburgCellShapes() =>
        HoltburgCells.Fixtures.OrderBy(c => c.Key).SelectMany(c => Cell(c.Key, c.Value.EnvCell, c.Value.CellStruct));

    /// <summary>Every portal of the real Holtburg cells placed in double precision: the cell, the cell it leads to (low 16 bits; 0xFFFF outdoors) and its polygon.</summary>
    public static IEnumerable<(uint Cell, ushort Other, V3[] Polygon)> HoltburgPortals()
    {
        foreach ((uint id, CellFixtureReader.FixtureCell cell) in HoltburgCells.Fixtures.OrderBy(c => c.Key))
        {
            foreach (CellPortal portal in cell.EnvCell.CellPortals)
            {
                V3[] polygon = [.. cell.CellStruct.Polygons[portal.PolygonId].VertexIds
                    .Select(i => V3.Of(AcDream.Testing.ReferenceBody.Place(cell.EnvCell.Position, cell.CellStruct.VertexArray.Vertices[(ushort)i].Origin)))];
                yield return (id, portal.OtherCellId, polygon);
            }
        }
    }

    /// <summary>
    /// The portals of the real cells that lead to cells the fixtures lack (0x013F, 0x016F): the engine stops a cast there
    /// as at a wall of the cell that holds the portal.
    /// </summary>
    public static IEnumerable<Shape> MissingCellPortals() =>
        CastReference.MissingPortals([.. HoltburgCells.Fixtures.Select(c => (c.Key, c.Value.EnvCell, c.Value.CellStruct))]);

    /// <summary>The cottage's shell and the small building (building shells), placed by their frames.</summary>
    public static IEnumerable<Shape> HoltburgBuildingShapes()
    {
        foreach (BuildingInfo building in ObjectPlacements.HoltburgInfo().Buildings)
        {
            foreach (Shape s in Model(RealObjects.GfxObjs[building.ModelId], building.Frame, SurfaceKind.BuildingShell, building.ModelId))
            {
                yield return s;
            }
        }
    }

    /// <summary>The two cellar stairs (objects standing in their cellars; their vertices are landblock-local, their frame the identity).</summary>
    public static IEnumerable<Shape> CellarStairShapes() =>
        ObjectPlacements.CellarStairs().SelectMany(s => Model(s.Stair, new Frame(), SurfaceKind.ObjectWall, s.Stair.Id));

    /// <summary>
    /// <see cref="RealObjects.HoltburgWithCellarStairs"/>: the real cells, the buildings and the cellar stairs on flat
    /// terrain at 94 m (and the flat south neighbour); the reference with the terrain and the buildings' shells or
    /// without them (a cast that stays indoors meets neither: the ground and the shells are the outdoors' and do not
    /// reach into cells; the cottage shell's base, at 94 m, spans the house and its stairwell).
    /// </summary>
    public static CastScene Holtburg(string frame, bool terrain, bool shells = true)
    {
        var shapes = new List<Shape>();
        shapes.AddRange(HoltburgCellShapes());
        shapes.AddRange(CellarStairShapes());
        if (shells)
        {
            shapes.AddRange(HoltburgBuildingShapes());
        }

        if (terrain)
        {
            shapes.AddRange(Terrain(Flat(94f), TestData.Holtburg, default));
            shapes.AddRange(Terrain(Flat(94f), South, new V3(0, -192, 0)));
        }

        return new CastScene(RealObjects.HoltburgWithCellarStairs(frame), frame, TestData.Holtburg, shapes) { GeometryRounding = RealGeometry };
    }

    /// <summary>
    /// Holtburg as an outdoor cast meets it: the ground, the buildings' shells and the walls (ceilings among them) of
    /// the cells, which are all reached from the outdoors through their doors; not the cells' floors or the objects
    /// standing in cells, which are met only from inside.
    /// </summary>
    public static CastScene HoltburgOutdoors(string frame)
    {
        var shapes = new List<Shape>();
        shapes.AddRange(HoltburgCellShapes().Where(s => s.Kind != SurfaceKind.CellFloor));
        shapes.AddRange(HoltburgBuildingShapes());
        shapes.AddRange(Terrain(Flat(94f), TestData.Holtburg, default));
        shapes.AddRange(Terrain(Flat(94f), South, new V3(0, -192, 0)));
        return new CastScene(RealObjects.HoltburgWithCellarStairs(frame), frame, TestData.Holtburg, shapes) { GeometryRounding = RealGeometry };
    }

    /// <summary>Where the segment a–b passes through the convex polygon (its plane crossed inside it); null for nowhere.</summary>
    public static double? Crossing(V3[] polygon, V3 a, V3 b)
    {
        V3 n = UnitNormal(polygon);
        double da = V3.Dot(a - polygon[0], n), db = V3.Dot(b - polygon[0], n);
        if (da * db > 0 || da == db)
        {
            return null;
        }

        double t = da / (da - db);
        V3 p = a + ((b - a) * t);
        for (int i = 0, j = polygon.Length - 1; i < polygon.Length; j = i++)
        {
            if (V3.Dot(V3.Cross(polygon[i] - polygon[j], p - polygon[j]), n) < -1e-9)
            {
                return null;
            }
        }

        return t;
    }

    /// <summary>The cottage's west door slab (<see cref="ObjectPlacements.DoorSlab"/>), its landblock-local origin and orientation.</summary>
    public static (GfxObj Slab, Vector3 Origin, Quaternion Orientation) WestDoor() =>
        ObjectPlacements.DoorSlab(HoltburgCells.Fixtures[ObjectPlacements.CottageWestDoorCell], 0xFFFF, ObjectPlacements.CottageWestDoorSlab);

    /// <summary>A mover's walls for the reference: a GfxObj's polygons that are not floors, placed at a landblock-local origin and orientation.</summary>
    public static IEnumerable<Shape> MoverWalls(GfxObj model, Vector3 origin, Quaternion orientation, uint id) =>
        Model(model, new Frame { Origin = origin, Orientation = orientation }, SurfaceKind.Mover, id, floors: false);

    /// <summary>A cylinder mover standing on a landblock-local point.</summary>
    public static Shape MoverCylinder(Vector3 feet, float radius, float height, uint id) =>
        new CastReference.Cylinder(feet.X, feet.Y, radius, feet.Z, (double)feet.Z + height, SurfaceKind.Mover, id, FormattableString.Invariant($"mover 0x{id:X8}"));
}
