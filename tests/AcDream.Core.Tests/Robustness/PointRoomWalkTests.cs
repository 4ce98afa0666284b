using System.Numerics;
using AcDream.Core.Physics;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Seeded random walks of a point mover among random rooms (issue 29, item 9), with the options a player's point uses
/// (step 0.5 m, step down 1.5 m, walkable slope, sweeps of 0.48 m, doors only): 80,000 frames per seed over 20 worlds,
/// each a row of rooms (doorways, door cells, raised floors and ramps, floor openings over cellars) or six cells of
/// random polygons, over random terrain, in the global frame, one centred on the landblock or one centred across the
/// world. Every answer's <c>IsOnGround</c> is true exactly when its Z is within the ground tolerance of the terrain or
/// of a floor of its cell under its XY, as a brute-force reference in double precision finds them
/// (<see cref="Reference.TerrainZ"/>, <see cref="Reference.FloorZs"/>), not the engine's own sampling. The returned XY
/// is exactly where the engine sampled (the world frame's representable point), so the reference is in doubt only
/// within float arithmetic of landblock-local metres of a triangle's tolerance boundary or of the ground tolerance.
/// </summary>
public class PointRoomWalkTests(ITestOutputHelper output)
{
    private const float Step = 0.5f;

    private static readonly MovementOptions Options = new()
    {
        StepDownHeight = 1.5f,
        WalkableSlope = true,
        SweepStepLength = 0.48f,
        DoorsOnly = true,
    };

    /// <summary>An engine in the global frame, one centred on <paramref name="id"/>, or one centred on the landblock across the world from it (48 km away at the corners).</summary>
    private static (PhysicsEngine Engine, bool Global) Engine(Random random, uint id) => random.Next(3) switch
    {
        0 => (new PhysicsEngine(), true),
        1 => (new PhysicsEngine(id), false),
        _ => (new PhysicsEngine(((0xFEu - (id >> 24)) << 24) | ((0xFEu - ((id >> 16) & 0xFF)) << 16) | 0xFFFFu), false),
    };

    /// <summary>One random world: a landblock of random terrain with six cells of random polygons, portals among them and to the outdoors.</summary>
    private sealed record World(PhysicsEngine Engine, uint Id, bool Global, byte[] Heights, float[] Table, List<CellSurface> Cells, Dictionary<uint, List<Reference.Triangle>> Floors)
    {
        public Vector3 Origin => Engine.GetLandblockOrigin(Id);
    }

    private static World Build(Random random) => random.Next(2) == 0 ? Polygons(random) : Rooms(random);

    /// <summary>
    /// A row of two to five rooms along the cells' x axis (one yaw, each its own cell with its floor up to 0.8 m above or
    /// below its neighbour's), joined by doorways or 0.4 m door cells, the first one's west doorway to the outdoors; in
    /// each room raised floors (platforms, and ramps that are walkable or too steep) a step or more above its floor.
    /// </summary>
    private static World Rooms(Random random)
    {
        int lbX = random.Next(1, 254), lbY = random.Next(1, 254);
        uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
        uint prefix = id & 0xFFFF0000u;
        (PhysicsEngine engine, bool global) = Engine(random, id);
        float floor = Gen.Range(random, 5, 80);
        var origin = new Vector2(Gen.Range(random, 40, 100), Gen.Range(random, 40, 150));
        Quaternion q = Gen.Orientation(random, sloppy: random.Next(3) == 0);
        int rooms = random.Next(2, 6);
        float d = Gen.Range(random, 3, 8), x = 0f, z = floor;
        var builders = new List<CellBuilder>();
        int next = 0;
        (float From, float To, float Top, ushort Other)? west = null;
        for (int r = 0; r < rooms; r++)
        {
            var room = new CellBuilder(prefix | (uint)(0x0100 + next++), new Vector3(origin, z), q);
            builders.Add(room);
            float w = Gen.Range(random, 3, 8), y0 = Gen.Range(random, 0.1f, d - 1.5f), y1 = MathF.Min(y0 + Gen.Range(random, 0.9f, 2.5f), d - 0.1f);
            if (r == 0)
            {
                west = (y0, y1, 2.3f, 0xFFFF);
            }

            (float, float, float, ushort)? east = null;
            float nextZ = z + Gen.Range(random, -0.8f, 0.8f);
            bool doorCell = random.Next(3) == 0;
            if (r + 1 < rooms)
            {
                east = (y0, y1, 2.3f, (ushort)(0x0100 + next + (doorCell ? 1 : 0)));
            }

            bool cellar = random.Next(2) == 0;
            BodyCourses.Box(room, x, 0, x + w, d, floor: !cellar, east: east, west: west, split: random);
            if (cellar)
            {
                // An opening in the floor (a horizontal portal) over a cellar a little or far below.
                float hx0 = Gen.Range(random, x + 0.3f, x + w - 1.3f), hx1 = Gen.Range(random, hx0 + 0.8f, x + w - 0.2f);
                float hy0 = Gen.Range(random, 0.3f, d - 1.3f), hy1 = Gen.Range(random, hy0 + 0.8f, d - 0.2f), depth = Gen.Range(random, 0.3f, 3.5f);
                room.Floor(x, 0, hx0, d, 0).Floor(hx1, 0, x + w, d, 0).Floor(hx0, 0, hx1, hy0, 0).Floor(hx0, hy1, hx1, d, 0);
                var below = new CellBuilder(prefix | (uint)(0x0200 + r), new Vector3(origin, z - depth), q);
                builders.Add(below);
                BodyCourses.Box(below, hx0 - 0.5f, hy0 - 0.5f, hx1 + 0.5f, hy1 + 0.5f, split: random);
                room.Portal((ushort)(below.CellId & 0xFFFF), new Vector3((hx0 + hx1) / 2, (hy0 + hy1) / 2, 1), CellBuilder.Square(hx0, hy0, hx1, hy1, 0));
                below.Portal((ushort)(room.CellId & 0xFFFF), new Vector3((hx0 + hx1) / 2, (hy0 + hy1) / 2, depth / 2), CellBuilder.Square(hx0, hy0, hx1, hy1, depth));
            }

            for (int p = random.Next(0, 4); p > 0; p--)
            {
                float px = Gen.Range(random, x, x + w - 0.5f), py = Gen.Range(random, 0, d - 0.5f), sx = Gen.Range(random, 0.4f, 3), sy = Gen.Range(random, 0.4f, 3);
                float h = Gen.Range(random, 0.1f, 1.2f), rise = random.Next(3) == 0 ? Gen.Range(random, 0.2f, 2.5f) * sx : 0f;
                (float x0, float x1, float ya, float yb) = (px, MathF.Min(px + sx, x + w), py, MathF.Min(py + sy, d));
                room.Physics(new Vector3(x0, ya, h), new Vector3(x1, ya, h + rise), new Vector3(x1, yb, h + rise), new Vector3(x0, yb, h));
            }

            if (r + 1 < rooms)
            {
                ushort self = (ushort)(room.CellId & 0xFFFF);
                float gap = 0f;
                if (doorCell)
                {
                    gap = 0.4f;
                    var door = new CellBuilder(prefix | (uint)(0x0100 + next++), new Vector3(origin, z), q);
                    builders.Add(door);
                    door.Floor(x + w, y0, x + w + gap, y1, 0);
                    door.Physics(BodyCourses.Wall(x + w, y0, x + w + gap, y0, 0, 2.3f)).Physics(BodyCourses.Wall(x + w + gap, y1, x + w, y1, 0, 2.3f));
                    var inside = new Vector3(x + w + (gap / 2), (y0 + y1) / 2, 1);
                    door.Portal(self, inside, BodyCourses.Opening(x + w, y0, y1, 2.3f));
                    door.Portal((ushort)(0x0100 + next), inside, BodyCourses.Opening(x + w + gap, y0, y1, 2.3f));
                    self = (ushort)(door.CellId & 0xFFFF);
                }

                west = (y0, y1, 2.3f, self);
                x += w + gap;
                z = nextZ;
            }
        }

        byte[] heights = Gen.Heights(random);
        float low = floor - Gen.Range(random, 0, 2), table0 = random.Next(2) == 0 ? 0.05f : 0.5f;
        float[] table = Enumerable.Range(0, 256).Select(i => low + (table0 * (i - 128) / 10f)).ToArray();
        var cells = builders.Select(b => b.Build()).ToList();
        engine.AddLandblock(id, new TerrainSurface(heights, table, id), cells);
        var floors = builders.ToDictionary(b => b.CellId, b => Reference.FloorTriangles(b.EnvCell, b.CellStruct));
        return new World(engine, id, global, heights, table, cells, floors);
    }

    /// <summary>Six cells of random polygons (floors of any slope, walls, ceilings, bad polygons) over random terrain, with portals among them and to the outdoors.</summary>
    private static World Polygons(Random random)
    {
        int lbX = random.Next(3) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(1, 254) };
        int lbY = random.Next(3) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(1, 254) };
        uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
        (PhysicsEngine engine, bool global) = Engine(random, id);
        byte[] heights = Gen.Heights(random);
        float[] table = Gen.HeightTable(random);
        var cells = new List<CellSurface>();
        var floors = new Dictionary<uint, List<Reference.Triangle>>();
        for (int c = 0; c < 6; c++)
        {
            var origin = new Vector3(Gen.Range(random, 10, 182), Gen.Range(random, 10, 182), Gen.Range(random, -50, 300));
            var builder = new CellBuilder((id & 0xFFFF0000u) | (uint)(0x0100 + c), origin, Gen.Orientation(random, sloppy: true));
            for (int p = random.Next(1, 6); p > 0; p--)
            {
                builder.Physics(Gen.Polygon(random, 6));
            }

            builder.Portal((ushort)(0x0100 + random.Next(6)), new Vector3(0, 0, 1), Wall(-3, -3, -3, 3, -1, 3));
            builder.Portal(0xFFFF, new Vector3(0, 0, 1), Wall(3, 3, 3, -3, -1, 3));
            cells.Add(builder.Build());
            floors[builder.CellId] = Reference.FloorTriangles(builder.EnvCell, builder.CellStruct);
        }

        engine.AddLandblock(id, new TerrainSurface(heights, table, id), cells);
        return new World(engine, id, global, heights, table, cells, floors);
    }

    [Theory]
    [InlineData(2901)]
    [InlineData(2902)]
    public void Resolve_PointWalksAmongRandomRooms_IsOnGroundExactlyWhereTheGroundIs(int seed)
    {
        var random = new Random(seed);
        int answers = 0, checkedAnswers = 0, onGround = 0, indoors = 0, wrong = 0;
        string? first = null;
        for (int w = 0; w < 20; w++)
        {
            World world = Build(random);
            ResolveResult at = default;
            for (int frame = 0; frame < 4000; frame++)
            {
                if (frame % 200 == 0 || at.Outcome == ResolveOutcome.Held)
                {
                    at = Start(world, random);
                }

                float heading = (float)(random.NextDouble() * 2 * Math.PI), length = Gen.Range(random, 0.02, random.Next(10) == 0 ? 3 : 0.6);
                var delta = new Vector3(MathF.Cos(heading) * length, MathF.Sin(heading) * length, 0f);
                ResolveResult r = world.Engine.Resolve(at.Position, at.CellId, delta, Step, Options);
                answers++;
                string what = FormattableString.Invariant($"seed {seed}, world {w} (0x{world.Id:X8}, {(world.Global ? "global" : "centred " + world.Origin.ToString())}), frame {frame}: {at.Position:R} in 0x{at.CellId:X8} by {delta:R}");
                if (Honest(world, r) is (bool stands, string ground))
                {
                    checkedAnswers++;
                    if (r.IsOnGround != stands)
                    {
                        wrong++;
                        first ??= $"{what} → {r}; {ground}";
                    }
                }

                onGround += r.IsOnGround ? 1 : 0;
                indoors += CellIds.IsIndoor(r.CellId) ? 1 : 0;

                // The walker's gravity, in every other world: an answer in the air falls 0.3 m before its next move (else it walks on in the air).
                at = r.IsOnGround || w % 2 == 0 ? r : r with { Position = r.Position - new Vector3(0f, 0f, 0.3f) };
            }
        }

        output.WriteLine($"seed {seed}: {answers} answers, {checkedAnswers} checked, {onGround} on the ground, {indoors} indoors, {wrong} dishonest; first: {first}");
        wrong.Should().Be(0, $"IsOnGround is true exactly where the reference finds ground under the answer; first: {first}");
        checkedAnswers.Should().BeGreaterThan(answers * 9 / 10, "nearly every answer is clear of the references' tolerance boundaries");
        indoors.Should().BeGreaterThan(answers / 5, "a good share of the walks is indoors");
    }

    /// <summary>A start on the terrain or on a cell's floor (or at its origin's height), settled by a zero move.</summary>
    private static ResolveResult Start(World world, Random random)
    {
        Vector3 offset = world.Origin;
        CellSurface? cell = random.Next(3) != 0 ? world.Cells[random.Next(world.Cells.Count)] : null;
        List<Reference.Triangle> floors = cell is null ? [] : world.Floors[cell.CellId];
        Vector2 local = cell is null
            ? new Vector2(Gen.Range(random, 2, 190), Gen.Range(random, 2, 190))
            : floors.Count == 0 || random.Next(4) == 0
                ? new Vector2(cell.Origin.X, cell.Origin.Y) + new Vector2(Gen.Range(random, -6, 6), Gen.Range(random, -6, 6))
                : InTriangle(floors[random.Next(floors.Count)], random);
        var terrain = new TerrainSurface(world.Heights, world.Table, world.Id);
        float z = cell is null ? terrain.SampleZ(local.X, local.Y) : cell.SampleFloorZ(local.X, local.Y, cell.Origin.Z) ?? cell.Origin.Z;
        uint id = cell?.CellId ?? (world.Id & 0xFFFF0000u);
        z += Gen.Range(random, random.Next(4) == 0 ? -2 : 0, 1);
        return new ResolveResult(offset + new Vector3(local, z), id, true);
    }

    /// <summary>A random point of a floor triangle (landblock-local XY).</summary>
    private static Vector2 InTriangle(Reference.Triangle t, Random random)
    {
        double u = random.NextDouble(), v = random.NextDouble();
        (u, v) = u + v > 1 ? (1 - u, 1 - v) : (u, v);
        return new Vector2((float)(t.A.X + (u * (t.B.X - t.A.X)) + (v * (t.C.X - t.A.X))), (float)(t.A.Y + (u * (t.B.Y - t.A.Y)) + (v * (t.C.Y - t.A.Y))));
    }

    /// <summary>
    /// Whether the answer stands on the ground by the reference, and what the reference found; null where the
    /// reference is in doubt (within 1e-4 m plus the world frame's rounding of a floor's edge or of the tolerance).
    /// </summary>
    private static (bool Stands, string Ground)? Honest(World world, ResolveResult r)
    {
        if (r.Outcome == ResolveOutcome.Held || (r.CellId & 0xFFFF0000u) != (world.Id & 0xFFFF0000u))
        {
            return null;
        }

        Vector3 offset = world.Origin;
        double x = (double)r.Position.X - offset.X, y = (double)r.Position.Y - offset.Y;
        // The answer's world XY is exactly where the engine sampled its ground (the world frame's representable point),
        // so the doubt is the float arithmetic of landblock-local metres (1.5e-5 m at 192 m) and of the Z.
        const double spacing = 1.6e-5;
        List<double> zs;
        double gradient;
        if (CellIds.IsIndoor(r.CellId))
        {
            (zs, bool ambiguous, _) = Reference.FloorZs(world.Floors[r.CellId], x, y, margin: 3 * spacing);
            if (ambiguous)
            {
                return null;
            }

            gradient = 2; // a floor's slope is at most 1/FloorZ's tangent (1.13); the clamped edge rule adds no more
        }
        else
        {
            if (x is < 0 or > 192 || y is < 0 or > 192)
            {
                return null;
            }

            zs = [Reference.TerrainZ(world.Heights, world.Table, (int)(world.Id >> 24), (int)((world.Id >> 16) & 0xFF), x, y)];
            gradient = Reference.MaxGradient(world.Heights, world.Table);
        }

        double doubt = 1e-5 + (Math.Abs(r.Position.Z) * 3e-7) + (gradient * spacing);
        double nearest = zs.Count == 0 ? double.PositiveInfinity : zs.Min(z => Math.Abs(r.Position.Z - z));
        if (Math.Abs(nearest - PhysicsConstants.GroundTolerance) < doubt)
        {
            return null;
        }

        return (nearest <= PhysicsConstants.GroundTolerance, $"reference ground Zs {string.Join(", ", zs.Select(z => z.ToString("R")))}");
    }
}
