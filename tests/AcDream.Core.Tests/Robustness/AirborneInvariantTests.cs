using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Behavior;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Random jumps and falls of the player's body through the real Holtburg cells and among its buildings, in both world
/// frames: every answer, on the ground or in the air, is a fixed point with honest ground (see
/// <see cref="VerticalMotionTests.Invariants"/>), never NaN, and every jump comes down.
/// </summary>
public class AirborneInvariantTests(ITestOutputHelper output)
{
    private const float Frame = 1f / 30f;

    [Theory]
    [InlineData("centred", 1)]
    [InlineData("global", 2)]
    [InlineData("centred", 8)]
    [InlineData("centred", 10)]
    public void Jumps_and_falls_give_fixed_points_with_honest_ground(string frame, int seed)
    {
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        List<ObjectSurface> objects = RealObjects.HoltburgBuildings();
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), objects);
        MovementOptions options = MovementOptions.Player;
        var random = new Random(seed);
        uint[] rooms = [0xA9B40143, 0xA9B40141, 0xA9B40171, 0xA9B40144, 0xA9B4014D];
        int answers = 0, airborne = 0, headHits = 0, landings = 0;
        for (int walk = 0; walk < 40; walk++)
        {
            bool indoor = walk % 2 == 0;
            uint cell = indoor ? rooms[random.Next(rooms.Length)] : 0xA9B40000;
            Vector3 local = indoor
                ? HoltburgCells.Surface(cell).GetFloorTriangles()[0] is var t ? (t.A + t.B + t.C) / 3f : default
                : new Vector3(130f + (float)(random.NextDouble() * 40), (float)(random.NextDouble() * 40), 94f);
            ResolveResult at = engine.Resolve(engine.ToWorld(TestData.Holtburg, local), cell, Vector3.Zero, 0.6f, options);
            float vz = 0f;
            for (int f = 0; f < 120; f++)
            {
                if (at.IsOnGround && random.Next(20) == 0)
                {
                    vz = (float)(random.NextDouble() * 9); // a jump of up to 4 m
                }

                float dz = 0f;
                if (!at.IsOnGround || vz > 0f)
                {
                    float before = vz;
                    vz = MathF.Max(vz - (9.8f * Frame), -50f);
                    dz = 0.5f * (before + vz) * Frame;
                }

                double heading = random.NextDouble() * 2 * Math.PI, speed = random.NextDouble() * 5;
                var delta = new Vector3((float)(Math.Cos(heading) * speed * Frame), (float)(Math.Sin(heading) * speed * Frame), dz);
                string what = $"{frame}, walk {walk}, frame {f}: {at.Position:R} in 0x{at.CellId:X8} by {delta:R}";
                bool wasAirborne = !at.IsOnGround;
                ResolveResult r = engine.Resolve(at.Position, at.CellId, delta, 0.6f, options);
                VerticalMotionTests.Invariants(engine, r, options, objects, what);
                answers++;
                airborne += r.IsOnGround ? 0 : 1;
                headHits += r.Outcome == ResolveOutcome.Ceiling ? 1 : 0;
                landings += wasAirborne && r.IsOnGround ? 1 : 0;
                if (r.Outcome == ResolveOutcome.Ceiling || (r.IsOnGround && vz <= 0f))
                {
                    vz = r.Outcome == ResolveOutcome.Ceiling ? MathF.Min(vz, 0f) : 0f;
                }

                at = r;
            }
        }

        output.WriteLine($"{frame}: {answers} answers, {airborne} in the air, {headHits} head hits, {landings} landings");
        answers.Should().Be(40 * 120);
        airborne.Should().BeGreaterThan(answers / 10, "many answers are in the air");
        landings.Should().BeGreaterThan(20, "the jumps come down");
        headHits.Should().BeGreaterThan(0, "some jumps indoors meet a ceiling");
    }
}
