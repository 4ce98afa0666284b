using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>, things that move: <see cref="MovementOptions.Player"/> walking at standing and walking creatures and
/// at closed doors at 1–50 m/s in both world frames, measured in double precision against <see cref="MoverReference"/>;
/// and what a move names as touched against the double-precision distance of its path. Seeded (5); a few seconds.
/// </summary>
internal static class MoverAccuracy
{
    private const uint Landblock = 0x7A3BFFFF, Cell = 0x7A3B001C;
    private const float Ground = 50f, Frame = 1f / 30f, Touch = 0.96f, Radius = 0.48f;
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;
    private static readonly MoverShape Human = MoverShape.Cylinder(Radius, 1.835f);

    public static void Run(TextWriter o)
    {
        o.WriteLine("## Things that move (movers)");
        o.WriteLine();
        o.WriteLine("`MovementOptions.Player` at 30 Hz on flat ground, 1–50 m/s, from random directions and offsets, in the centred and the");
        o.WriteLine("global frame. A creature is a cylinder 0.48 m × 1.835 m (the body's surface meets it at 0.96 m between axes); a door the");
        o.WriteLine("game's slab (0.261 m thick, 1.2 m wide, 2.2 m high) at a random turn. Distances in double precision (`tests/Shared/MoverReference.cs`);");
        o.WriteLine("inside is negative clearance.");
        o.WriteLine();
        o.WriteLine("| measure | value |");
        o.WriteLine("| --- | ---: |");
        var random = new Random(5);
        Creatures(o, random, moving: false);
        Creatures(o, random, moving: true);
        Doors(o, random);
        Touches(o, random);
        o.WriteLine();
    }

    private static PhysicsEngine Field(bool global)
    {
        PhysicsEngine engine = global ? new PhysicsEngine() : new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, new TerrainSurface(new byte[81], World.ConstantTable(Ground), Landblock), []);
        return engine;
    }

    private static Vector3 At(PhysicsEngine engine, Vector2 local) => engine.ToWorld(Landblock, new Vector3(local, Ground));

    private static Vector2 Direction(Random random)
    {
        double a = random.NextDouble() * 2 * Math.PI;
        return new Vector2((float)Math.Cos(a), (float)Math.Sin(a));
    }

    private static void Creatures(TextWriter o, Random random, bool moving)
    {
        int runs = 0, met = 0;
        double worst = double.MaxValue, gapSum = 0;
        for (int n = 0; n < 400; n++)
        {
            PhysicsEngine engine = Field(n % 2 == 1);
            float speed = 1f + (random.NextSingle() * 49f);
            Vector2 dir = Direction(random), side = new Vector2(-dir.Y, dir.X) * ((random.NextSingle() * 2f) - 1f);
            var body = new ResolveResult(At(engine, new Vector2(96f) - (dir * 4f)), Cell, true);
            var creature = new ResolveResult(At(engine, new Vector2(96f) + side + (moving ? dir * 4f : Vector2.Zero)), Cell, true);
            engine.Movers.Add(1, Human, body.Position, Cell, Quaternion.Identity, MoverState.Player);
            engine.Movers.Add(2, Human, creature.Position, Cell, Quaternion.Identity, MoverState.Creature);
            engine.Movers.Commit();
            double nearest = double.MaxValue;
            for (int f = 0; f < (int)(9f / (speed * Frame)) + 2; f++)
            {
                if (moving)
                {
                    creature = engine.Resolve(creature.Position, creature.CellId, new Vector3(-dir * speed * Frame, 0f), World.PlayerStepUp, MovementOptions.Player, 2u);
                    engine.Movers.Move(2, creature.Position, creature.CellId, Quaternion.Identity);
                    engine.Movers.Commit();
                    nearest = Math.Min(nearest, MoverReference.Apart(body.Position, creature.Position));
                }

                body = engine.Resolve(body.Position, body.CellId, new Vector3(dir * speed * Frame, 0f), World.PlayerStepUp, MovementOptions.Player, 1u);
                engine.Movers.Move(1, body.Position, body.CellId, Quaternion.Identity);
                engine.Movers.Commit();
                nearest = Math.Min(nearest, MoverReference.Apart(body.Position, creature.Position));
            }

            runs++;
            worst = Math.Min(worst, nearest - Touch);
            if (nearest < Touch + 0.01)
            {
                (met, gapSum) = (met + 1, gapSum + (nearest - Touch));
            }
        }

        string what = moving ? "walking at each other" : "at a standing creature";
        o.WriteLine(string.Create(Inv, $"| body {what}: runs / met | {runs} / {met} |"));
        o.WriteLine(string.Create(Inv, $"| body {what}: least clearance (m) | {worst:0.000000} |"));
        o.WriteLine(string.Create(Inv, $"| body {what}: mean clearance when met (m) | {gapSum / Math.Max(met, 1):0.000000} |"));
    }

    private static void Doors(TextWriter o, Random random)
    {
        int runs = 0, stopped = 0;
        double worst = double.MaxValue;
        for (int n = 0; n < 300; n++)
        {
            PhysicsEngine engine = Field(n % 2 == 1);
            double yaw = random.NextDouble() * 2 * Math.PI;
            Vector3 centre = At(engine, new Vector2(96f));
            engine.Movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), centre, Cell, MoverReference.Yaw(yaw), MoverState.Door);
            engine.Movers.Commit();
            float speed = 1f + (random.NextSingle() * 49f);
            var across = new Vector2((float)-Math.Sin(yaw), (float)Math.Cos(yaw));
            var along = new Vector2(across.Y, -across.X);
            float sign = n % 4 < 2 ? 1f : -1f;
            Vector2 aim = (along * ((random.NextSingle() * 1.2f) - 0.6f)) + (sign * across * 3f);
            Vector2 dir = Vector2.Normalize(-(sign * across) + (along * ((random.NextSingle() * 0.6f) - 0.3f)));
            var body = new ResolveResult(At(engine, new Vector2(96f) + aim), Cell, true);
            double nearest = double.MaxValue;
            for (int f = 0; f < (int)(6f / (speed * Frame)) + 2; f++)
            {
                body = engine.Resolve(body.Position, body.CellId, new Vector3(dir * speed * Frame, 0f), World.PlayerStepUp, MovementOptions.Player);
                nearest = Math.Min(nearest, MoverReference.ToSlab(body.Position, centre, yaw, 0.6));
            }

            runs++;
            worst = Math.Min(worst, nearest - Radius);
            stopped += nearest < Radius + 0.01 ? 1 : 0;
        }

        o.WriteLine(string.Create(Inv, $"| body at a closed door, both sides: runs / reached it | {runs} / {stopped} |"));
        o.WriteLine(string.Create(Inv, $"| body at a closed door: least clearance (m) | {worst:0.000000} |"));
    }

    private static void Touches(TextWriter o, Random random)
    {
        // An Ethereal swirl (a cylinder of 1 m) and random straight moves near it: named as touched exactly when the
        // double-precision distance from the path to its axis is under the radii (1.48 m), away from a band of 1 mm.
        int moves = 0, agree = 0, band = 0;
        Span<uint> touched = stackalloc uint[2];
        for (int n = 0; n < 2000; n++)
        {
            PhysicsEngine engine = Field(n % 2 == 1);
            Vector3 swirl = At(engine, new Vector2(96f));
            engine.Movers.Add(3, MoverShape.Cylinder(1f, 2f), swirl, Cell, Quaternion.Identity, new MoverState(MoverKind.Object, PhysicsStateFlags.Ethereal));
            engine.Movers.Commit();
            Vector3 start = At(engine, new Vector2(96f) + (Direction(random) * (1.5f + (random.NextSingle() * 2f))));
            var delta = new Vector3(Direction(random) * (random.NextSingle() * 3f), 0f);
            ResolveResult r = engine.Resolve(start, Cell, delta, World.PlayerStepUp, MovementOptions.Player, 0u, touched, out int count, out _);
            double distance = MoverReference.SegmentTo(start, r.Position, swirl);
            if (Math.Abs(distance - 1.48) < 0.001)
            {
                band++;
                continue;
            }

            moves++;
            agree += (count == 1) == (distance < 1.48) ? 1 : 0;
        }

        o.WriteLine(string.Create(Inv, $"| an Ethereal mover named as touched as the path's distance says: agree / moves | {agree} / {moves} ({band} within 1 mm left out) |"));
    }
}
