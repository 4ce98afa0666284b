using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>First checks of the body: a slide along a wall, a stop in a corner, no tunnelling at speed.</summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class BodySmokeTests
{
    private static readonly MovementOptions WithBody = new() { Body = new MoverBody(0.5f, 1.8f) };

    /// <summary>A 10 × 10 room (cell-local −5..5) at landblock-local (100, 100, 50), walls 3 m high, no portals.</summary>
    private static (PhysicsEngine Engine, uint Cell, Vector3 Centre) Room()
    {
        uint cell = (Holtburg & 0xFFFF0000u) | 0x0100;
        var b = new CellBuilder(cell, new Vector3(100, 100, 50));
        b.Floor(-5, -5, 5, 5, 0);
        b.Physics(Wall(5, -5, 5, 5, 0, 3)).Physics(Wall(5, 5, -5, 5, 0, 3)).Physics(Wall(-5, 5, -5, -5, 0, 3)).Physics(Wall(-5, -5, 5, -5, 0, 3));
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(50f), [new CellSurface(cell, b.EnvCell, b.CellStruct)]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        return (engine, cell, new Vector3(origin.X + 100, origin.Y + 100, 50));
    }

    [Fact]
    public void Resolve_DiagonallyIntoAWall_SlidesAlongItAtTheRadius()
    {
        (PhysicsEngine engine, uint cell, Vector3 centre) = Room();
        // From 0.8 m off the east wall (x = 5), 0.6 m east and north: contact half way, then along the wall.
        var r = engine.Resolve(centre + new Vector3(4.2f, 0, 0), cell, new Vector3(0.6f, 0.6f, 0), 0.5f, WithBody);
        r.Outcome.Should().Be(ResolveOutcome.Slid, r.ToString());
        (centre.X + 5f - r.Position.X).Should().BeApproximately(0.5f, 0.001f, r.ToString());
        (r.Position.Y - centre.Y).Should().BeApproximately(0.6f, 0.001f, r.ToString());
        r.SurfaceNormal.X.Should().BeApproximately(-1f, 1e-4f, r.ToString());
    }

    [Fact]
    public void Resolve_PushingIntoACorner_StopsAndStaysBitForBit()
    {
        (PhysicsEngine engine, uint cell, Vector3 centre) = Room();
        var pos = centre;
        ResolveResult r = default;
        var seen = new List<Vector3>();
        for (int i = 0; i < 60; i++)
        {
            r = engine.Resolve(pos, cell, new Vector3(0.3f, 0.25f, 0), 0.5f, WithBody);
            seen.Add(r.Position);
            pos = r.Position;
        }

        seen.Skip(40).Distinct().Should().HaveCount(1, string.Join(", ", seen.Skip(40)));
        (centre.X + 5f - r.Position.X).Should().BeApproximately(0.5f, 0.001f, r.ToString());
        (centre.Y + 5f - r.Position.Y).Should().BeApproximately(0.5f, 0.001f, r.ToString());
        r.Outcome.Should().Be(ResolveOutcome.Wall, r.ToString());
    }

    [Theory]
    [InlineData(5f)]
    [InlineData(20f)]
    public void Resolve_FastIntoAWall_StopsAtTheRadius(float metres)
    {
        (PhysicsEngine engine, uint cell, Vector3 centre) = Room();
        var r = engine.Resolve(centre, cell, new Vector3(metres, 0, 0), 0.5f, WithBody);
        (centre.X + 5f - r.Position.X).Should().BeApproximately(0.5f, 0.001f, r.ToString());
        r.CellId.Should().Be(cell);
    }

    [Fact]
    public void Resolve_HeadOnIntoAWallWithARoundingSizedSidewaysPart_IsStoppedNotSlidInPlace()
    {
        // A heading of east from MathF.SinCos(π/2) leaves a sideways part of about 3e-9 of the move.
        (PhysicsEngine engine, uint cell, Vector3 centre) = Room();
        ResolveResult first = engine.Resolve(centre + new Vector3(4f, 0, 0), cell, new Vector3(1f, 0, 0), 0.5f, WithBody);
        ResolveResult r = engine.Resolve(first.Position, cell, new Vector3(0.06666667f, -2.9140927E-09f, 0), 0.5f, WithBody);
        r.Outcome.Should().Be(ResolveOutcome.Wall, $"{first} then {r}");
        r.Position.Should().Be(first.Position, $"{first} then {r}");
        r.SurfaceNormal.X.Should().BeApproximately(-1f, 1e-4f, r.ToString());
    }
}
