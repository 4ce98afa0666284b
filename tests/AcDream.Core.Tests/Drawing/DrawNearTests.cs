using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.App.Fixtures;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Drawing;

/// <summary>
/// <see cref="PhysicsEngine.DrawNear{TSink}"/> on the real Holtburg cells, their buildings and cellar stairs: every point
/// drawn lies on the geometry its kind and id name, to 1e-4 m (plus, in the global frame, the float rounding of a world
/// coordinate there, about 3 mm): cells' walls, floors and portals on the fixtures' polygons placed in the landblock,
/// objects' on their own walls and floors, terrain on the terrain's surface, a mover's cylinder on its radius.
/// </summary>
public class DrawNearTests(ITestOutputHelper output)
{
    private const uint MainRoom = 0xA9B40143;
    private const float Tolerance = 1e-4f;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    [Theory]
    [MemberData(nameof(Frames))]
    public void Every_segment_near_the_cottage_lies_on_the_geometry_it_names(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        Vector3 moverAt = origin + new Vector3(120f, 12f, 94f);
        engine.Movers.Add(7, MoverShape.Cylinder(0.5f, 2f), moverAt, 0, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var sink = new RecordingSink();
        engine.DrawNear(origin + new Vector3(145f, 10f, 94f), MainRoom, 30f, ref sink);

        Dictionary<uint, List<Vector3[]>> physics = CellPolygons(c => c.CellStruct.PhysicsPolygons.Values);
        Dictionary<uint, List<Vector3[]>> portals = CellPolygons(c => c.EnvCell.CellPortals.Select(p => c.CellStruct.Polygons[p.PolygonId]));
        List<ObjectSurface> objects = HoltburgObjects();
        var checkedCount = new Dictionary<DrawKind, int>();
        foreach (Drawn d in sink.All)
        {
            Vector3 landblock = engine.GetLandblockOrigin(d.Kind == DrawKind.Terrain ? d.Id : TestData.Holtburg);
            // The points in the landblock's frame (world − origin is exact), and how far rounding to the world frame may
            // have moved them. (A cylinder's ring is drawn as chords: their ends are on its radius, their midpoints inside it.)
            Vector3[] corners = d.Points.Select(p => p - landblock).ToArray();
            float tolerance = Tolerance + d.Points.Max(Distances.Rounding);
            foreach (Vector3 local in d.Kind is DrawKind.Cylinder or DrawKind.Mover ? corners : Samples(corners))
            {
                float off = d.Kind switch
                {
                    DrawKind.Terrain => MathF.Abs(local.Z - 94f), // both landblocks are flat at 94 m (the hills: below)
                    DrawKind.CellFloor or DrawKind.CellWall => physics[d.Id].Min(p => Distances.ToPolygon(local, p)),
                    DrawKind.Portal => portals[d.Id].Min(p => Distances.ToPolygon(local, p)),
                    DrawKind.ObjectFloor => objects.Where(o => o.ObjectId == d.Id).SelectMany(o => o.GetFloorTriangles())
                        .Min(t => Distances.ToTriangle(local, t.A, t.B, t.C)),
                    DrawKind.ObjectWall => objects.Where(o => o.ObjectId == d.Id).SelectMany(o => o.GetWalls()).Where(w => w.Radius == 0f)
                        .Min(w => Distances.ToPolygon(local, w.Outline)),
                    DrawKind.Cylinder => objects.Where(o => o.ObjectId == d.Id).SelectMany(o => o.GetWalls()).Where(w => w.Radius > 0f)
                        .Min(w => CylinderOff(local, w.Outline[0], w.Radius, w.Outline[1].Z - w.Outline[0].Z)),
                    DrawKind.Mover => CylinderOff(local, moverAt - landblock, 0.5f, 2f),
                    _ => throw new InvalidOperationException($"{d.Kind} is not drawn by DrawNear"),
                };
                off.Should().BeLessThanOrEqualTo(tolerance, $"{frame}: {d.Kind} of 0x{d.Id:X8} at {local} (landblock-local)");
            }

            checkedCount[d.Kind] = checkedCount.GetValueOrDefault(d.Kind) + 1;
        }

        foreach (DrawKind kind in new[] { DrawKind.Terrain, DrawKind.CellFloor, DrawKind.CellWall, DrawKind.Portal, DrawKind.ObjectFloor, DrawKind.ObjectWall, DrawKind.Mover })
        {
            checkedCount.GetValueOrDefault(kind).Should().BePositive($"{frame}: the cottage's neighbourhood has {kind}");
        }

        sink.Of(DrawKind.CellWall).Select(d => d.Id).Should().Contain(MainRoom);
        sink.All.Where(d => d.Kind == DrawKind.Mover).Should().OnlyContain(d => d.Id == 7u);
        output.WriteLine($"[{frame}] " + string.Join(", ", checkedCount.OrderBy(k => k.Key).Select(k => $"{k.Key} {k.Value}")));

        // A cylinder (base, radius, height): how far a point is from its radius around its axis, or from its bottom and top.
        static float CylinderOff(Vector3 p, Vector3 bottom, float radius, float height)
        {
            Vector3 d = p - bottom;
            return MathF.Max(MathF.Abs(new Vector2(d.X, d.Y).Length() - radius), MathF.Min(MathF.Abs(d.Z), MathF.Abs(d.Z - height)));
        }
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void Terrain_triangles_on_hills_lie_on_the_terrain_and_cover_the_square(string frame)
    {
        (PhysicsEngine engine, TerrainSurface terrain) = HoltburgCells.OnHills(new Random(32), frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        var sink = new RecordingSink();
        engine.DrawNear(origin + new Vector3(60f, 100f, 150f), TestData.Holtburg & 0xFFFF0000u, 20f, ref sink);
        Drawn[] triangles = sink.Of(DrawKind.Terrain).ToArray();
        triangles.Should().HaveCount(2 * 3 * 3, "the square 40..80 × 80..120 meets 3 × 3 outdoor cells, two triangles each");
        foreach (Drawn t in triangles)
        {
            (t.Id & 0xFFFF0000u).Should().Be(TestData.Holtburg & 0xFFFF0000u);
            float tolerance = Tolerance + t.Points.Max(Distances.Rounding);
            foreach (Vector3 local in Samples(t.Points.Select(p => p - origin).ToArray()))
            {
                MathF.Abs(local.Z - terrain.SampleZ(local.X, local.Y)).Should().BeLessThanOrEqualTo(tolerance, $"{frame}: at {local}");
            }

            Vector3 centre = ((t.Points[0] + t.Points[1] + t.Points[2]) / 3f) - origin;
            t.Id.Should().Be(0xA9B40000u | terrain.ComputeOutdoorCellId(centre.X, centre.Y), "a triangle is named by its outdoor cell");
            Vector3.Cross(t.Points[1] - t.Points[0], t.Points[2] - t.Points[0]).Z.Should().BePositive("counter-clockwise seen from above");
        }
    }

    [Fact]
    public void A_struct_sink_near_the_cottage_allocates_nothing()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        Vector3 at = engine.ToWorld(TestData.Holtburg, new Vector3(145f, 10f, 94f));
        var sink = new CountingStruct();
        engine.DrawNear(at, MainRoom, 20f, ref sink);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            engine.DrawNear(at, MainRoom, 20f, ref sink);
        }

        (GC.GetAllocatedBytesForCurrentThread() - before).Should().Be(0);
        (sink.Lines + sink.Triangles).Should().BeGreaterThan(101 * 100, "it drew the cottage each time");
    }

    [Fact]
    public void Bad_arguments_are_refused_by_name()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        var sink = new CountingSink();
        CountingSink? none = null;
        Vector3 at = engine.ToWorld(TestData.Holtburg, new Vector3(145f, 10f, 94f));
        ((Action)(() => engine.DrawNear(at, MainRoom, float.NaN, ref sink))).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("radius");
        ((Action)(() => engine.DrawNear(at, MainRoom, -1f, ref sink))).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("radius");
        ((Action)(() => engine.DrawNear(at, MainRoom, 193f, ref sink))).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("radius");
        ((Action)(() => engine.DrawNear(at with { X = float.NaN }, MainRoom, 1f, ref sink))).Should().Throw<ArgumentException>().WithParameterName("position");
        ((Action)(() => engine.DrawNear(at, 0xA9B40041u, 1f, ref sink))).Should().Throw<ArgumentException>().WithParameterName("cellId");
        ((Action)(() => engine.DrawNear(at, MainRoom, 1f, ref none!))).Should().Throw<ArgumentNullException>().WithParameterName("sink");
        ((Action)(() => engine.DrawMove(new MoveRequest(at, MainRoom, Vector3.Zero, 0.5f), null!))).Should().Throw<ArgumentNullException>().WithParameterName("sink");
        sink.Counts.Sum().Should().Be(0, "nothing is drawn by a refused call");
    }

    /// <summary>A drawn element's corners, and the midpoints of its edges.</summary>
    private static IEnumerable<Vector3> Samples(Vector3[] points)
    {
        for (int i = 0; i < points.Length; i++)
        {
            yield return points[i];
            yield return 0.5f * (points[i] + points[(i + 1) % points.Length]);
        }
    }

    /// <summary>Each fixture cell's polygons (chosen by <paramref name="select"/>), placed in the landblock as the fixture's position says.</summary>
    private static Dictionary<uint, List<Vector3[]>> CellPolygons(Func<CellFixtureReader.FixtureCell, IEnumerable<Polygon>> select) =>
        HoltburgCells.Fixtures.Values.ToDictionary(
            c => c.CellId,
            c => select(c).Select(p => p.VertexIds.Select(id => c.EnvCell.Position!.Origin
                + Vector3.Transform(c.CellStruct.VertexArray.Vertices[(ushort)id].Origin, Quaternion.Normalize(c.EnvCell.Position.Orientation))).ToArray()).ToList());

    /// <summary>The objects <see cref="RealObjects.HoltburgWithCellarStairs"/> registers: the buildings and the cellar stairs.</summary>
    private static List<ObjectSurface> HoltburgObjects()
    {
        var gfxObjs = new Dictionary<uint, GfxObj>(RealObjects.GfxObjs);
        var cells = new List<EnvCell>();
        foreach ((uint cellId, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
        {
            gfxObjs.TryAdd(stair.Id, stair);
            cells.Add(new EnvCell { Id = cellId, StaticObjects = [placement] });
        }

        return ObjectSurface.FromLandblock(TestData.Holtburg, ObjectPlacements.HoltburgInfo(), cells, gfxObjs, RealObjects.NoSetups);
    }
}
