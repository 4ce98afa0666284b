using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>Tiny, huge and zero moves and step-height boundaries: deterministic, documented answers.</summary>
[Trait("Mutation", "PortalTraversal")]
public class MoveTests
{
    private const uint A = 0x1010FFFFu;

    private static PhysicsEngine Engine(TerrainSurface? terrain = null)
    {
        var engine = new PhysicsEngine(A);
        engine.AddLandblock(A, terrain ?? new TerrainSurface(Heights((x, y) => (x * 2) + y), LinearTable(), A), []);
        return engine;
    }

    [Theory]
    [InlineData(100f, 1e-7f, 100f)]            // below half the float spacing at 100 m (3.8e-6 m): lost
    [InlineData(100f, 4e-6f, 100.00000763f)]   // just above it: one float step
    [InlineData(0.5f, 1e-7f, 0.5000001f)]      // near the landblock's corner the spacing is 6e-8 m
    [InlineData(100f, 1e-30f, 100f)]
    [InlineData(100f, float.Epsilon, 100f)]
    public void Resolve_TinyMove_DeterministicFloatRounding(float x, float dx, float expectedX)
    {
        PhysicsEngine engine = Engine();
        var pos = new Vector3(x, 50, 0);
        ResolveResult first = engine.Resolve(pos, 0, new Vector3(dx, 0, 0), 100f);
        first.Position.X.Should().Be(expectedX, $"{x} + {dx} in landblock-local float");
        for (int i = 0; i < 100; i++)
        {
            engine.Resolve(pos, 0, new Vector3(dx, 0, 0), 100f).Should().Be(first, "the same input always gives the same answer");
        }
    }

    [Fact]
    public void Resolve_ZeroDelta_IsIdempotentOnTheGround()
    {
        PhysicsEngine engine = Engine();
        var random = new Random(31);
        for (int n = 0; n < 2000; n++)
        {
            var pos = new Vector3(Gen.Range(random, 0, 192), Gen.Range(random, 0, 192), Gen.Range(random, 0, 100));
            ResolveResult once = engine.Resolve(pos, 0, Vector3.Zero, 1000f);
            ResolveResult twice = engine.Resolve(once.Position, once.CellId, Vector3.Zero, 1000f);
            once.Position.X.Should().Be(pos.X, $"case {n}: {pos:R}");
            once.Position.Y.Should().Be(pos.Y, $"case {n}: {pos:R}");
            twice.Should().Be(once, $"case {n}: standing still changes nothing after the first snap to the ground ({pos:R})");
        }
    }

    [Fact]
    public void Resolve_HugeMoves_EndPointTestedLandOrRejectedNeverNaN()
    {
        // 0x1010 and 0x2A10 (26 landblocks = 4992 m east) registered: a 4992 m delta is an end-point
        // move and lands there; a move to unregistered land or off the world is rejected.
        PhysicsEngine engine = Engine();
        engine.AddLandblock(0x2A10FFFFu, FlatTerrain(7f, 0x2A10FFFFu), []);
        var pos = new Vector3(100, 50, 0);
        ResolveResult start = engine.Resolve(pos, 0, Vector3.Zero, 0f);

        ResolveResult far = engine.Resolve(start.Position, start.CellId, new Vector3(4992, 0, 0), 10f);
        far.Should().Be(new ResolveResult(new Vector3(5092, 50, 7), 0x2A100023u, true), "the spec's end-point check: a kilometre move lands where it ends");

        foreach (float d in new[] { 1000f, 1e6f, -1e6f, 1e30f, float.MaxValue, -float.MaxValue })
        {
            foreach (Vector3 delta in new[] { new Vector3(d, 0, 0), new Vector3(0, d, 0), new Vector3(d, d, 1e30f) })
            {
                ResolveResult r = engine.Resolve(start.Position, start.CellId, delta, 10f);
                (r.Position, r.CellId, r.IsOnGround).Should().Be((start.Position, start.CellId, start.IsOnGround), $"delta {delta}: unregistered land or off the world");
                r.Outcome.Should().BeOneOf([ResolveOutcome.UnloadedAhead, ResolveOutcome.EdgeOfWorld], $"delta {delta}");
            }
        }
    }

    [Fact]
    public void Resolve_StepHeightZero_FlatAndDownhillOnlyAndExactlyEqualAccepted()
    {
        // Terrain rising 2 m per 24 m along +x (Z = x / 12).
        PhysicsEngine engine = Engine(new TerrainSurface(Heights((x, _) => x), LinearTable(), A));
        var pos = new Vector3(60, 50, 5);
        engine.Resolve(pos, 0, new Vector3(0, 1, 0), 0f).Position.Should().Be(new Vector3(60, 51, 5), "flat along y: a rise of 0 is within a step of 0");
        engine.Resolve(pos, 0, new Vector3(-1.2f, 0, 0), 0f).Position.Z.Should().BeApproximately(4.9f, 1e-5f, "downhill");
        engine.Resolve(pos, 0, new Vector3(1.2f, 0, 0), 0f).Position.Should().Be(pos, "any rise exceeds a step of 0");

        // Exactly equal to the step height: accepted (the boundary is inclusive), one float step more: rejected.
        float rise = engine.Resolve(pos, 0, new Vector3(1.5f, 0, 0), 100f).Position.Z - pos.Z;
        rise.Should().BeGreaterThan(0f);
        engine.Resolve(pos, 0, new Vector3(1.5f, 0, 0), rise).Position.Z.Should().Be(pos.Z + rise, "a rise of exactly the step height is accepted");
        engine.Resolve(pos, 0, new Vector3(1.5f, 0, 0), MathF.BitDecrement(rise)).Position.Should().Be(pos, "one float step less is not enough");
    }

    [Fact]
    public void Resolve_IndoorStepExactlyTheStepHeight_AcceptedAndOneFloatStepLessRejected()
    {
        CellSurface stairs = new CellBuilder(0x10100100u, new Vector3(40, 40, 3)).Floor(0, 0, 2, 4, 0).Floor(2, 0, 4, 4, 0.37f).Build();
        var engine = new PhysicsEngine(A);
        engine.AddLandblock(A, FlatTerrain(-20f, A), [stairs]);
        var pos = new Vector3(41.8f, 42, 3);
        float top = stairs.SampleFloorZ(42.5f, 42)!.Value, rise = top - pos.Z;
        engine.Resolve(pos, stairs.CellId, new Vector3(0.7f, 0, 0), rise).Position.Z.Should().Be(top);
        engine.Resolve(pos, stairs.CellId, new Vector3(0.7f, 0, 0), MathF.BitDecrement(rise)).Position.Should().Be(pos);
        engine.Resolve(new Vector3(42.5f, 42, top), stairs.CellId, new Vector3(-0.7f, 0, 0), 0f).Position.Z.Should().Be(3f, "stepping down needs no step height");
    }
}
