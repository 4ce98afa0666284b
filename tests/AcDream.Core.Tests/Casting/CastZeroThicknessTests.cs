using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Nothing passes a surface of zero thickness, in both world frames: rays and spheres from either side at random points
/// of one wall polygon, exactly at the shared edge of two coplanar walls, and at the shared corner of four floor
/// polygons (whose fan triangles add diagonals), each with the centre ending on its own side and the contact where the
/// reference puts it. (The terrain's shared edges and vertices: <see cref="CastTerrainTests"/>.)
/// </summary>
public class CastZeroThicknessTests(ITestOutputHelper output)
{
    private const uint Wall = 0x01FF0B01, Pair = 0x01FF0B02, Floors = 0x01FF0B03;

    /// <summary>Objects on flat ground at 94 m in Holtburg: one wall 4 × 3 m (yaw 0.5), two walls sharing an edge (yaw 1.1), and four 2 × 2 m floor squares meeting at a corner 2 m up (yaw 0.3).</summary>
    private static (CastScene Scene, (V3[] Polygon, V3 Normal, string Where)[] Targets) Surfaces(string frame)
    {
        Frame Placed(float x, float yaw) => new() { Origin = new Vector3(x, 100, 94), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw) };
        GfxObj wall = DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = Wall, Flags = GfxObjFlags.HasPhysics }, [TestData.Wall(-2, 0, 2, 0, 0, 3)]);
        GfxObj pair = DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = Pair, Flags = GfxObjFlags.HasPhysics }, [TestData.Wall(-2, 0, 0, 0, 0, 3), TestData.Wall(0, 0, 2, 0, 0, 3)]);
        GfxObj floors = DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = Floors, Flags = GfxObjFlags.HasPhysics }, [
            CellBuilder.Square(-2, -2, 0, 0, 2), CellBuilder.Square(0, -2, 2, 0, 2), CellBuilder.Square(0, 0, 2, 2, 2), CellBuilder.Square(-2, 0, 0, 2, 2)]);
        (GfxObj Model, Frame At)[] objects = [(wall, Placed(100, 0.5f)), (pair, Placed(120, 1.1f)), (floors, Placed(140, 0.3f))];
        PhysicsEngine engine = CastWorlds.NewEngine(frame);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], [.. objects.Select(o => new ObjectSurface(o.Model, o.At, 0))]);
        var shapes = new List<Shape>(CastWorlds.Terrain(CastWorlds.Flat(94f), TestData.Holtburg, default));
        foreach ((GfxObj model, Frame at) in objects)
        {
            shapes.AddRange(Model(model, at, SurfaceKind.ObjectWall, model.Id));
        }

        var scene = new CastScene(engine, frame, TestData.Holtburg, shapes) { GeometryRounding = CastWorlds.RealGeometry };
        V3 P(Frame at, float x, float y, float z) => V3.Of(ReferenceBody.Place(at, new Vector3(x, y, z)));
        V3 wallNormal = UnitNormal([P(objects[0].At, -2, 0, 0), P(objects[0].At, 2, 0, 0), P(objects[0].At, 2, 0, 3)]);
        V3 pairNormal = UnitNormal([P(objects[1].At, -2, 0, 0), P(objects[1].At, 2, 0, 0), P(objects[1].At, 2, 0, 3)]);
        (V3[], V3, string)[] targets =
        [
            ([P(objects[0].At, -2, 0, 0), P(objects[0].At, 2, 0, 0), P(objects[0].At, 2, 0, 3), P(objects[0].At, -2, 0, 3)], wallNormal, "anywhere on the wall"),
            ([P(objects[1].At, 0, 0, 0.2f), P(objects[1].At, 0, 0, 2.8f)], pairNormal, "on the walls' shared edge"),
            ([P(objects[2].At, 0, 0, 2)], new V3(0, 0, 1), "at the floors' shared corner"),
            ([P(objects[2].At, -1.9f, 0, 2), P(objects[2].At, 1.9f, 0, 2)], new V3(0, 0, 1), "on the floors' shared edge"),
        ];
        return (scene, targets);
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Rays_and_spheres_at_a_zero_thickness_wall_its_shared_edges_and_corner_never_pass(string frame)
    {
        (CastScene scene, (V3[] Polygon, V3 Normal, string Where)[] targets) = Surfaces(frame);
        var random = new Random(71);
        var worst = new Deviations(frame);
        foreach ((V3[] polygon, V3 n, string where) in targets)
        {
            for (int k = 0; k < 300; k++)
            {
                // A point of the target: inside the polygon, or on the edge, or the corner itself.
                V3 target = polygon.Length switch
                {
                    1 => polygon[0],
                    2 => polygon[0] + ((polygon[1] - polygon[0]) * random.NextDouble()),
                    _ => polygon[0] + ((polygon[1] - polygon[0]) * random.NextDouble()) + ((polygon[3] - polygon[0]) * random.NextDouble()),
                };
                float r = k % 3 == 0 ? 0f : k % 3 == 1 ? 0.05f : 0.3f;
                int side = k % 2 == 0 ? 1 : -1;
                V3 d = new V3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * 2;
                d -= n * V3.Dot(d, n);
                V3 dir = (n * -side) + (d * 0.9); // from the side `side` of it, across at 48° or more from the surface
                dir *= 1.0 / dir.Length;
                V3 start = target - (dir * (0.5 + r + (random.NextDouble() * 3))), end = target + (dir * (0.05 + r + (random.NextDouble() * 2)));
                if (start.Z < 94 + r + 0.01 || end.Z < 94.01 || scene.Clearance(start) < r + 0.01)
                {
                    continue; // under the ground, or starting within its radius of the surfaces
                }

                Vector3 from = scene.World(start), to = scene.World(end);
                CastHit hit = scene.Engine.Cast(from, 0, to, new CastOptions(r));
                string what = $"{where}, case {k}, from the {(side > 0 ? "front" : "back")}, r {r}: {hit}";
                hit.Hit.Should().BeTrue(what);
                double stays = V3.Dot(scene.Local(hit.Position) - target, n) * side;
                stays.Should().BeGreaterThanOrEqualTo(-1e-4 - CastScene.HalfSpacing(hit.Position), $"the centre stays on its side: {what}");
                scene.Tally(hit, scene.Expected(from, to, r), from, to, r, worst, what);
            }
        }

        output.WriteLine(worst.ToString());
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        worst.Hits.Should().BeGreaterThan(900);
    }
}
