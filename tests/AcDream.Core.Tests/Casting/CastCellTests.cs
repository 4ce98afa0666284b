using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Casts from inside cells against <see cref="CastReference"/>, in both world frames (in the global frame positions are
/// compared in landblock-local terms within their float rounding, and the travel to the contact exactly): random rays
/// and spheres in the real Holtburg rooms (walls, floors, ceilings, the cellar stair), casts grazing the walls, floor
/// and ceiling of a room of exact float geometry at 0.002–0.05 rad and the real rooms' at 0.1–0.3 rad, spheres passing
/// within their radius of edges and corners, and casts through doorways whose answer names the cell at their end.
/// </summary>
public class CastCellTests(ITestOutputHelper output)
{
    private const uint Cellar = ObjectPlacements.CottageCellar;
    private const uint MainRoom = 0xA9B40143, DoorCell = 0xA9B40145, Hall = 0xA9B40141, Stairwell = 0xA9B40146;

    /// <summary>Boxes inside real rooms (landblock-local) random starts are drawn from, each kept only if a ray down from it meets its cell's floor.</summary>
    private static readonly (uint Cell, V3 Lo, V3 Hi)[] Rooms =
    [
        (MainRoom, new V3(136.9, 4.1, 94.1), new V3(141.9, 12.9, 96.7)),
        (Hall, new V3(136.9, 13.6, 94.1), new V3(141.9, 18.8, 96.7)),
        (Cellar, new V3(136.9, -0.9, 91.0), new V3(141.9, 11.4, 93.7)),
        (0xA9B40148, new V3(128.6, -0.9, 91.0), new V3(133.4, 11.4, 93.7)),
        (0xA9B4014D, new V3(136.9, 4.1, 97.1), new V3(142.2, 19.1, 98.5)),
        (0xA9B40172, new V3(158.2, 4.6, 94.1), new V3(164.7, 10.6, 96.5)),
        (0xA9B40171, new V3(153.1, 6.5, 94.1), new V3(157.7, 15.0, 96.5)),
    ];

    private static readonly float[] Radii = [0f, 0.3f, 0.1f, 0.5f];

    /// <summary>
    /// The contact a cast from a cell has: the world without terrain and shells (they are the outdoors' and do not reach
    /// into cells), unless the centre passes out through one of the buildings' outdoor portals before that contact, when
    /// they count.
    /// </summary>
    private static Hit? Expected(CastScene indoors, CastScene withGround, V3[][] outdoorPortals, V3 a, V3 b, float r)
    {
        Hit? inside = indoors.Reference.Cast(a, b, r);
        double end = inside?.T ?? 1.0;
        bool leaves = outdoorPortals.Any(p => CastWorlds.Crossing(p, a, b) is double t && t < end);
        return leaves ? withGround.Reference.Cast(a, b, r) : inside;
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Random_rays_and_spheres_in_the_real_rooms_meet_what_the_reference_does(string frame)
    {
        CastScene indoors = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        indoors.Shapes.AddRange(CastWorlds.MissingCellPortals());
        var withGround = new CastScene(indoors.Engine, frame, TestData.Holtburg, indoors.Shapes.Concat(CastWorlds.Holtburg(frame, terrain: true).Shapes.Where(s => s.Kind is SurfaceKind.Terrain or SurfaceKind.BuildingShell)))
        {
            GeometryRounding = CastWorlds.RealGeometry,
        };
        V3[][] outdoorPortals = [.. CastWorlds.HoltburgPortals().Where(p => p.Other == 0xFFFF).Select(p => p.Polygon)];
        var random = new Random(31);
        var worst = new Deviations(frame);
        var kinds = new Dictionary<SurfaceKind, int>();
        int skipped = 0;
        for (int n = 0; n < 1400; n++)
        {
            (uint cell, V3 lo, V3 hi) = Rooms[n % Rooms.Length];
            float r = Radii[(n / Rooms.Length) % Radii.Length];
            var start = new V3(lo.X + (random.NextDouble() * (hi.X - lo.X)), lo.Y + (random.NextDouble() * (hi.Y - lo.Y)), lo.Z + (random.NextDouble() * (hi.Z - lo.Z)));
            Hit? down = indoors.Reference.Cast(start, start - new V3(0, 0, 10), 0);
            if (down is null || down.Shape.Kind is not (SurfaceKind.CellFloor or SurfaceKind.ObjectFloor) || (down.Shape.Kind == SurfaceKind.CellFloor && down.Shape.Id != cell)
                || indoors.Clearance(start) < r + 0.01)
            {
                skipped++; // not over this cell's floor (or over the cellar stair), or within the radius of a wall
                continue;
            }

            double azimuth = random.NextDouble() * 2 * Math.PI, elevation = (random.NextDouble() - 0.5) * Math.PI;
            V3 d = new V3(Math.Cos(azimuth) * Math.Cos(elevation), Math.Sin(azimuth) * Math.Cos(elevation), Math.Sin(elevation)) * (1 + (random.NextDouble() * 9));
            Vector3 from = indoors.World(start), to = indoors.World(start + d);
            CastHit hit = indoors.Engine.Cast(from, cell, to, new CastOptions(r));
            Hit? expected = Expected(indoors, withGround, outdoorPortals, indoors.Local(from), indoors.Local(to), r);
            indoors.Tally(hit, expected, from, to, r, worst, $"cast {n} from 0x{cell:X8}");
            kinds[hit.Kind] = kinds.GetValueOrDefault(hit.Kind) + 1;
        }

        output.WriteLine($"{worst}; {skipped} starts skipped; met: {string.Join(", ", kinds.OrderBy(k => k.Key).Select(k => $"{k.Key} {k.Value}"))}");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        worst.Hits.Should().BeGreaterThan(900);
        kinds.Keys.Should().Contain([SurfaceKind.CellWall, SurfaceKind.CellFloor, SurfaceKind.CellCeiling, SurfaceKind.ObjectWall, SurfaceKind.ObjectFloor]);
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Casts_grazing_the_real_rooms_walls_floors_and_ceilings_meet_them_where_the_reference_does(string frame)
    {
        // The real cells' vertices are placed by the engine in floats (their coordinates near 140 m are rounded by up to
        // 7.6e-6 m): at 0.1 rad that moves a contact along the path by up to 7.6e-5 m, within the 1e-4 m asked, so here
        // no allowance is made for it.
        CastScene holtburg = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        CastScene scene = new(holtburg.Engine, frame, TestData.Holtburg, holtburg.Shapes);
        var worst = new Deviations(frame);
        var random = new Random(32);
        (uint Cell, V3 Point, V3 Normal, V3 Along)[] faces =
        [
            (MainRoom, new V3(142.1, 8.5, 95.4), new V3(-1, 0, 0), new V3(0, 1, 0)), // east wall
            (MainRoom, new V3(139.4, 3.9, 95.4), new V3(0, 1, 0), new V3(1, 0, 0)), // south wall
            (MainRoom, new V3(139.0, 10.5, 94.0), new V3(0, 0, 1), new V3(0.6, -0.8, 0)), // floor
            (MainRoom, new V3(139.4, 8.5, 96.8), new V3(0, 0, -1), new V3(0, 1, 0)), // ceiling
            (Hall, new V3(142.1, 16.2, 95.4), new V3(-1, 0, 0), new V3(0, 1, 0)),
            (Cellar, new V3(142.1, 1.5, 92.4), new V3(-1, 0, 0), new V3(0, 1, 0)), // a cellar wall, across its panels
            (Cellar, new V3(138.5, 3.7, 90.95), new V3(0, 0, 1), new V3(0, 1, 0)), // the cellar floor, across its panels
            (Cellar, new V3(136.0, 4.0, 93.8), new V3(0, 0, -1), new V3(0, 1, 0)), // the cellar ceiling
        ];
        foreach ((uint cell, V3 point, V3 normal, V3 along) in faces)
        {
            foreach (double angle in new[] { 0.3, 0.2, 0.1 })
            {
                foreach (float r in new[] { 0f, 0.3f, 0.1f })
                {
                    double back = 1.2 + (random.NextDouble() * 0.5);
                    V3 w = (along * Math.Cos(angle)) - (normal * Math.Sin(angle));
                    V3 start = point + (normal * r) - (w * back);
                    Vector3 from = scene.World(start), to = scene.World(start + (w * (back + 1)));
                    CastHit hit = scene.Check(from, cell, to, r, worst, $"0x{cell:X8} face at {point}, angle {angle}");
                    hit.Hit.Should().BeTrue();
                }
            }
        }

        output.WriteLine(worst.ToString());
    }

    /// <summary>
    /// A room of exact float geometry: cell 0xA9B40100 at (100, 100, 50), 10 × 10 m, walls 3 m, a ceiling, a 1 m
    /// doorway to the outdoors in the south wall (x 4.5..5.5), and a free-standing zero-thickness partition from (5, 3) to
    /// (5, 7), 2 m high; on flat ground at 50 m.
    /// </summary>
    private static CastScene ExactRoom(string frame)
    {
        const uint cell = 0xA9B40100;
        var b = new CellBuilder(cell, new Vector3(100, 100, 50));
        b.Floor(0, 0, 10, 10, 0);
        b.Physics([.. CellBuilder.Square(0, 0, 10, 10, 3).Reverse()]); // the ceiling, facing down
        b.Physics(TestData.Wall(0, 0, 4.5f, 0, 0, 3)).Physics(TestData.Wall(5.5f, 0, 10, 0, 0, 3));
        b.Physics(TestData.Wall(10, 0, 10, 10, 0, 3)).Physics(TestData.Wall(10, 10, 0, 10, 0, 3)).Physics(TestData.Wall(0, 10, 0, 0, 0, 3));
        b.Physics(TestData.Wall(5, 3, 5, 7, 0, 2));
        b.Portal(0xFFFF, new Vector3(5, 5, 1), new(4.5f, 0, 0), new(5.5f, 0, 0), new(5.5f, 0, 2.5f), new(4.5f, 0, 2.5f));
        PhysicsEngine engine = CastWorlds.NewEngine(frame);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(50f), [b.Build()]);
        return new CastScene(engine, frame, TestData.Holtburg, Cell(cell, b.EnvCell, b.CellStruct));
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Casts_grazing_a_rooms_wall_floor_ceiling_and_partition_at_small_angles_meet_them_where_the_reference_does(string frame)
    {
        CastScene scene = ExactRoom(frame);
        var worst = new Deviations(frame);
        (V3 Point, V3 Normal, V3 Along)[] faces =
        [
            (new V3(110, 105, 51.5), new V3(-1, 0, 0), new V3(0, 1, 0)), // east wall
            (new V3(103, 110, 51.5), new V3(0, -1, 0), new V3(-1, 0, 0)), // north wall
            (new V3(104, 106, 50), new V3(0, 0, 1), new V3(0.6, 0.8, 0)), // floor
            (new V3(104, 106, 53), new V3(0, 0, -1), new V3(-0.6, -0.8, 0)), // ceiling
            (new V3(105, 105, 51), new V3(-1, 0, 0), new V3(0, 1, 0)), // the partition's west face
            (new V3(105, 105, 51), new V3(1, 0, 0), new V3(0, -1, 0)), // its east face
        ];
        foreach ((V3 point, V3 normal, V3 along) in faces)
        {
            foreach (double angle in new[] { 0.05, 0.01, 0.002 })
            {
                foreach (float r in new[] { 0f, 0.3f })
                {
                    V3 w = (along * Math.Cos(angle)) - (normal * Math.Sin(angle));
                    V3 start = point + (normal * r) - (w * 1.5);
                    Vector3 from = scene.World(start), to = scene.World(start + (w * 2.5));
                    CastHit hit = scene.Check(from, 0xA9B40100, to, r, worst, $"face at {point} facing {normal}, angle {angle}");
                    hit.Hit.Should().BeTrue();
                    hit.CellId.Should().Be(0xA9B40100u);
                }
            }
        }

        output.WriteLine(worst.ToString());
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Spheres_passing_within_their_radius_of_edges_and_corners_meet_them_where_the_reference_does(string frame)
    {
        // The partition's vertical end edges (x 5, y 3 and y 7), its top edge (z 2) and its top corners, and the
        // doorway's jambs (x 4.5 and 5.5 at y 0): passed at the radius less or more 1 cm or 1 mm, from many directions.
        CastScene scene = ExactRoom(frame);
        var worst = new Deviations(frame);
        var random = new Random(33);
        (V3 Point, V3 Away)[] edges =
        [
            (new V3(105, 103, 51), new V3(0, -1, 0)), (new V3(105, 107, 51), new V3(0, 1, 0)), // end edges
            (new V3(105, 105, 52), new V3(0, 0, 1)), // top edge
            (new V3(105, 103, 52), new V3(0, -0.6, 0.8)), (new V3(105, 107, 52), new V3(0, 0.6, 0.8)), // top corners
            (new V3(104.5, 100, 51), new V3(1, 0, 0)), (new V3(105.5, 100, 51), new V3(-1, 0, 0)), // the doorway's jambs, passed in the opening
        ];
        int met = 0, passed = 0;
        foreach ((V3 point, V3 away) in edges)
        {
            foreach (float r in new[] { 0.3f, 0.1f, 0.45f })
            {
                foreach (double by in new[] { -0.01, -0.001, 0.001, 0.01 })
                {
                    // A direction across the edge's plane (perpendicular to the offset), tilted at random.
                    V3 across = point.Z > 51.5 && away.Z > 0.99 ? new V3(1, 0, 0) : new V3(Math.Abs(away.X) > 0.5 ? 0 : 1, Math.Abs(away.X) > 0.5 ? 1 : 0, 0);
                    double tilt = (random.NextDouble() - 0.5) * 0.6;
                    V3 dir = (across * Math.Cos(tilt)) + (V3.Cross(across, away) * Math.Sin(tilt));
                    V3 closest = point + (away * (r + by));
                    V3 start = closest - (dir * 1.5), end = closest + (dir * 1.5);
                    if (scene.Clearance(start) < r + 0.001)
                    {
                        continue;
                    }

                    Vector3 from = scene.World(start), to = scene.World(end);
                    uint cell = scene.Local(from).Y < 100 ? 0xA9B40000u : 0xA9B40100u;
                    CastHit hit = scene.Check(from, cell, to, r, worst, $"edge at {point}, offset {away}·(r {r} + {by})");
                    met += hit.Hit ? 1 : 0;
                    passed += hit.Hit ? 0 : 1;
                }
            }
        }

        output.WriteLine($"{worst}; {met} met an edge, {passed} passed");
        met.Should().BeGreaterThan(40);
        passed.Should().BeGreaterThan(20);
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Casts_through_doorways_follow_the_portals_and_name_the_cell_at_their_end(string frame)
    {
        // Casts that pass out of a building meet the outdoors too (the ground, the shells); those that stay in do not.
        CastScene outdoors = CastWorlds.Holtburg(frame, terrain: true);
        CastScene scene = new(outdoors.Engine, frame, TestData.Holtburg, CastWorlds.Holtburg(frame, terrain: false, shells: false).Shapes) { GeometryRounding = CastWorlds.RealGeometry };
        var worst = new Deviations(frame);
        (string What, uint From, V3 Start, V3 End, float Radius, uint EndCell, bool Out)[] runs =
        [
            ("main room north through 0x0142 into the hall", MainRoom, new V3(139, 10, 95.9), new V3(139.2, 16, 95.8), 0.3f, Hall, false),
            ("hall south back into the main room", Hall, new V3(139.2, 16, 95.8), new V3(139, 10, 95.9), 0f, MainRoom, false),
            ("main room west out of the door 0x0145 to the yard", MainRoom, new V3(139, 5.15, 95.2), new V3(131, 5.3, 95.4), 0.3f, 0xA9B40029, true), // outdoor cell (5, 0)
            ("the yard east in through the door to the main room", 0, new V3(131, 5.3, 95.4), new V3(139, 5.15, 95.2), 0.3f, MainRoom, true),
            ("the yard into the door cell", 0, new V3(131, 5.15, 95.2), new V3(136.5, 5.15, 95.2), 0f, DoorCell, true),
            ("hall north out of the arched opening 0x014F", Hall, new V3(139.4, 16, 95.5), new V3(139.4, 23, 95.5), 0.25f, 0xA9B40029, true), // outdoor cell (5, 0)
            ("main room down the stairwell into 0x0146", MainRoom, new V3(141.3, 7.5, 95), new V3(141.3, 7.6, 93.9), 0.1f, Stairwell, false),
        ];
        foreach ((string what, uint cell, V3 start, V3 end, float r, uint endCell, bool leaves) in runs)
        {
            CastScene world = leaves ? outdoors : scene;
            Vector3 from = world.World(start), to = world.World(end);
            CastHit hit = world.Check(from, cell, to, r, worst, what);
            hit.Hit.Should().BeFalse($"{what}: {hit}");
            hit.CellId.Should().Be(endCell, $"{what}: {hit}");
        }

        // Down the stairwell onto the cellar stair's ramp: met in the cellar, two portals below the main room.
        Vector3 top = scene.World(new V3(141.3, 6.3, 95.5)), bottom = scene.World(new V3(141.3, 6.3, 92));
        CastHit stair = scene.Check(top, MainRoom, bottom, 0f, worst, "down the stairwell onto the stair");
        (stair.Kind, stair.Id, stair.CellId).Should().Be((SurfaceKind.ObjectFloor, ObjectPlacements.CottageCellarStair, Cellar), $"{stair}");
        output.WriteLine(worst.ToString());
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void A_ray_from_the_cottage_cellar_to_the_yard_is_stopped_in_the_cellar(string frame)
    {
        CastScene scene = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        var worst = new Deviations(frame);
        var random = new Random(34);
        for (int n = 0; n < 40; n++)
        {
            var start = new V3(137 + (random.NextDouble() * 3), 0 + (random.NextDouble() * 5), 91.5 + (random.NextDouble() * 2));
            var yard = new V3(100 + (random.NextDouble() * 30), 20 + (random.NextDouble() * 60), 94.5 + (random.NextDouble() * 3));
            CastHit hit = scene.Check(scene.World(start), Cellar, scene.World(yard), n % 2 == 0 ? 0f : 0.3f, worst, $"cellar {start} to the yard {yard}");
            hit.Hit.Should().BeTrue();
            hit.CellId.Should().BeOneOf([Cellar, 0xA9B40148u, 0xA9B40149u], $"west of the cellar are 0x0148 and 0x0149: {hit}");
            hit.Kind.Should().BeOneOf(SurfaceKind.CellCeiling, SurfaceKind.CellWall, SurfaceKind.CellFloor);
        }

        output.WriteLine(worst.ToString());
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void A_portal_to_a_cell_not_loaded_stops_a_cast_at_it_as_a_wall_of_its_cell(string frame)
    {
        // 0x0144's west portal leads to 0x013F, which the fixtures lack: a ray from the main room west through the
        // doorway 0x0143 → 0x0144 stops on that portal's plane (x 136.3), named as a wall of 0x0144.
        CastScene scene = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        scene.Shapes.AddRange(CastWorlds.MissingCellPortals());
        var worst = new Deviations(frame);
        foreach (float r in new[] { 0f, 0.3f })
        {
            Vector3 from = scene.World(new V3(139, 10.5, 95.2)), to = scene.World(new V3(133, 10.4, 95.3));
            CastHit hit = scene.Check(from, MainRoom, to, r, worst, $"west into 0x0144, radius {r}");
            (hit.Kind, hit.Id, hit.CellId).Should().Be((SurfaceKind.CellWall, 0xA9B40144u, 0xA9B40144u), $"{hit}");
        }

        output.WriteLine(worst.ToString());
    }
}
