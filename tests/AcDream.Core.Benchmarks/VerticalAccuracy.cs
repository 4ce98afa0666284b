using System.Globalization;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Testing.ReferenceBody;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>, the body in three dimensions (issue 19): <see cref="MovementOptions.Player"/>'s jumps under the real
/// cells' ceilings against <see cref="CeilingReference"/> (double precision, brute force), falls onto rolling terrain against
/// <see cref="ReferenceTerrain"/> and the analytic time, footing at a slab's edge against <see cref="FootingReference"/>, and
/// moves through surfaces of zero thickness. Seeded (5); a few seconds.
/// </summary>
internal static class VerticalAccuracy
{
    private const float Frame = 1f / 30f;
    private const float Gravity = 9.8f;

    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    public static void Run(TextWriter o)
    {
        o.WriteLine("## The body in three dimensions (vertical motion, footing, edge slide)");
        o.WriteLine();
        o.WriteLine("`MovementOptions.Player` at 30 Hz, the caller's vertical speed under gravity 9.8 m/s² passed in the delta (the displacement");
        o.WriteLine("exact for constant acceleration), zeroed by a landing or a head hit. References: `tests/Shared/CeilingReference.cs` (the lowest");
        o.WriteLine("point of the placed wall polygons over the body's disc, sampled in double precision on 48 rings × 192 angles and 400 points");
        o.WriteLine("per edge), `ReferenceTerrain` (the game's triangles in double) and `tests/Shared/FootingReference.cs` (support reach in double).");
        o.WriteLine();
        o.WriteLine("| measure | value |");
        o.WriteLine("| --- | ---: |");
        Ceilings(o);
        Falls(o);
        Footing(o);
        Through(o);
        o.WriteLine();
    }

    private static void Ceilings(TextWriter o)
    {
        var random = new Random(5);
        List<CellFixtureReader.FixtureCell> fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        List<World.WallFace> faces = World.Walls(fixtures);
        List<Vec3[]> walls = fixtures.SelectMany(c => WallsOf(c.EnvCell, c.CellStruct)).ToList();
        PhysicsEngine engine = World.IndoorEngine(surfaces);
        int jumps = 0, headHits = 0, redrawn = 0, frames = 0, leftCell = 0;
        double worstOver = double.NegativeInfinity, worstGap = 0;
        for (int n = 0; n < 400; n++)
        {
            (Vector3 start, uint cell) = World.IndoorStart(random, fixtures, surfaces, faces, ref redrawn);
            var at = engine.Resolve(start, cell, Vector3.Zero, World.PlayerStepUp, MovementOptions.Player);
            float vz = 3f + (random.NextSingle() * 6f);
            jumps++;
            for (int f = 0; f < 120 && (f == 0 || !at.IsOnGround); f++)
            {
                float before = vz;
                vz = MathF.Max(vz - (Gravity * Frame), -50f);
                at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0f, 0.5f * (before + vz) * Frame), World.PlayerStepUp, MovementOptions.Player);
                frames++;
                double top = at.Position.Z + MoverBody.Player.Height;
                double ceiling = CeilingReference.LowestOver(walls, at.Position.X, at.Position.Y, MoverBody.Player.Radius, top - 0.01);
                worstOver = Math.Max(worstOver, top - ceiling);
                if (at.Outcome == ResolveOutcome.Ceiling)
                {
                    headHits++;
                    worstGap = Math.Max(worstGap, ceiling - top);
                    vz = Math.Min(vz, 0f);
                }

                vz = at.IsOnGround ? 0f : vz;
            }

            leftCell += at.CellId != cell ? 1 : 0;
        }

        o.WriteLine($"| jumps of 3–9 m/s from random floor points of the 22 real cells (body clear of walls) | {jumps} jumps, {frames} frames, {headHits} head hits |");
        o.WriteLine($"| the top above the reference's ceiling, worst frame (m; negative: below) | {E(worstOver)} |");
        o.WriteLine($"| a head hit's gap under the reference's ceiling, worst (m) | {E(worstGap)} |");
        o.WriteLine($"| jumps straight up that came down in another cell | {leftCell} |");
    }

    private static void Falls(TextWriter o)
    {
        var random = new Random(5);
        float[] table = World.NonLinearTable();
        byte[] heights = World.RollingHeights(random, 60, 6);
        var engine = new PhysicsEngine(World.Holtburg);
        var terrain = new TerrainSurface(heights, table, World.Holtburg);
        engine.AddLandblock(World.Holtburg, terrain, []);
        var reference = new ReferenceTerrain(heights, table, World.Holtburg);
        int falls = 0, offByMore = 0;
        double worstZ = 0, worstTime = 0;
        for (int n = 0; n < 300; n++)
        {
            float x = 4f + (random.NextSingle() * 184f), y = 4f + (random.NextSingle() * 184f), h = 0.5f + (random.NextSingle() * 49.5f);
            var at = new ResolveResult(new Vector3(x, y, terrain.SampleZ(x, y) + h), (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y), false);
            float vz = 0f;
            int frames = 0;
            while (!at.IsOnGround && frames < 400)
            {
                float before = vz;
                vz = MathF.Max(vz - (Gravity * Frame), -50f);
                at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0f, 0.5f * (before + vz) * Frame), World.PlayerStepUp, MovementOptions.Player);
                frames++;
            }

            falls++;
            double ground = reference.Sample(x, y).Z;
            worstZ = Math.Max(worstZ, Math.Abs(at.Position.Z - ground));
            double analytic = Math.Sqrt(2 * (terrain.SampleZ(x, y) + h - ground) / Gravity);
            double late = (frames * Frame) - analytic;
            worstTime = Math.Max(worstTime, Math.Abs(late));
            offByMore += late < 0 || late > Frame ? 1 : 0;
        }

        o.WriteLine($"| falls of 0.5–50 m onto rolling terrain: landing Z against the reference, worst (m) | {E(worstZ)} over {falls} falls |");
        o.WriteLine($"| the same: landing frame after the analytic time √(2h/g), worst (s); landed before it or more than a frame after | {F(worstTime, "0.0000")}; {offByMore} |");
    }

    private static void Footing(TextWriter o)
    {
        var random = new Random(5);
        int points = 0, mismatches = 0, boundary = 0;
        for (int n = 0; n < 200; n++)
        {
            var engine = new PhysicsEngine(World.Holtburg);
            float yaw = random.NextSingle() * MathF.Tau, radius = 0.2f + (random.NextSingle() * 0.8f);
            GfxObj slab = DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = 0x01000200, Flags = GfxObjFlags.HasPhysics },
                [[new(-1, -1, 0), new(1, -1, 0), new(1, 1, 0), new(-1, 1, 0)]]);
            var placed = new ObjectSurface(slab, new Frame { Origin = new Vector3(96f, 96f, 98f), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw) }, 0);
            engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], World.ConstantTable(94f), World.Holtburg), [], [placed]);
            FloorTriangleInfo[] floors = placed.GetFloorTriangles();
            MovementOptions options = MovementOptions.Player with { Body = new MoverBody(radius, 1.835f) };
            for (int k = 0; k < 20; k++)
            {
                // Around the slab's edge: up to its radius past it and inside it.
                float angle = random.NextSingle() * MathF.Tau, d = 1f + ((random.NextSingle() - 0.3f) * radius * 1.4f);
                var local = new Vector2(96f, 96f) + (new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * d * 1.3f);
                double distance = floors.Min(t => FootingReference.Distance(t, local.X, local.Y));
                if (Math.Abs(distance - (radius * PhysicsConstants.SupportReach)) < 1e-4)
                {
                    boundary++;
                    continue; // on the reach's own boundary: float and double may round either way
                }

                ResolveResult r = engine.Resolve(new Vector3(local, 98f), (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(local.X, local.Y), Vector3.Zero, World.PlayerStepUp, options);
                bool held = FootingReference.Holds(floors, local, 98, radius);
                mismatches += r.IsOnGround != held ? 1 : 0;
                points++;
            }
        }

        o.WriteLine($"| footing at the edge of a turned 2 × 2 m slab 4 m up, radius 0.2–1 m: held or not against the reference | {mismatches} of {points} differ ({boundary} within 0.1 mm of the reach left out) |");
    }

    private static void Through(TextWriter o)
    {
        var engine = new PhysicsEngine(World.Holtburg);
        GfxObj slab = DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = 0x01000201, Flags = GfxObjFlags.HasPhysics },
            [[new(-3, -3, 0), new(3, -3, 0), new(3, 3, 0), new(-3, 3, 0)]]);
        engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], World.ConstantTable(94f), World.Holtburg), [],
            [new ObjectSurface(slab, new Frame { Origin = new Vector3(96f, 96f, 100f), Orientation = Quaternion.Identity }, 0)]);
        uint cell = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(96f, 96f);
        int moves = 0, past = 0;
        for (double speed = 0.25; speed <= 50; speed += 0.25)
        {
            float dz = (float)(speed * Frame);
            var down = new ResolveResult(new Vector3(96.3f, 95.7f, 100.001f + (3.5f * dz)), cell, false);
            var up = engine.Resolve(new Vector3(96.3f, 95.7f, 94f), cell, Vector3.Zero, World.PlayerStepUp, MovementOptions.Player);
            for (int f = 0; f < 6; f++)
            {
                down = engine.Resolve(down.Position, down.CellId, new Vector3(0f, 0f, -dz), World.PlayerStepUp, MovementOptions.Player);
                up = engine.Resolve(up.Position, up.CellId, new Vector3(0f, 0f, dz), World.PlayerStepUp, MovementOptions.Player);
                past += down.Position.Z < 100f ? 1 : 0;
                past += up.Position.Z + MoverBody.Player.Height > 100.001f ? 1 : 0;
                moves += 2;
            }
        }

        o.WriteLine($"| moves at 0.25–50 m/s down onto and up under a slab of zero thickness that end past it | {past} of {moves} |");
    }

    private static string F(double v, string format) => v.ToString(format, Inv);

    private static string E(double v) => v.ToString("0.00e+0", Inv);
}
