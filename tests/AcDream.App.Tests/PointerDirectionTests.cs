using System.Numerics;
using AcDream.App.Movement;
using AcDream.Core.Physics;
using static AcDream.App.Tests.TestWorlds;

namespace AcDream.App.Tests;

/// <summary>
/// Issue 29, defect 8: the pointer takes any finite direction that is not zero. Its length was measured in float, whose
/// square overflows above about 1.8e19 and underflows below about 1e-19, so such directions were refused as not finite or zero.
/// </summary>
public sealed class PointerDirectionTests
{
    [Theory]
    [InlineData(1e20f, 0f, -1e20f, 1f, 0f, -1f)]
    [InlineData(3e38f, 0f, 0f, 1f, 0f, 0f)]
    [InlineData(1e-23f, 0f, -1e-23f, 1f, 0f, -1f)]
    [InlineData(1e-30f, 0f, 0f, 1f, 0f, 0f)]
    [InlineData(float.Epsilon, 0f, -float.Epsilon, 1f, 0f, -1f)]
    [InlineData(float.MaxValue, -float.MaxValue, -float.MaxValue, 1f, -1f, -1f)]
    [InlineData(float.MaxValue, float.MaxValue, 0f, 1f, 1f, 0f)] // components whose sum overflows
    public void Cast_DirectionOfAnyFiniteLength_IsTheRayOfItsUnitDirection(float x, float y, float z, float ux, float uy, float uz)
    {
        PhysicsEngine engine = Engine(Heights((_, _) => 10)); // flat ground at 10 m
        var pointer = new Pointer(engine);
        var eye = new Vector3(50f, 96f, 20f); // 100 m east stays in the landblock

        PointerHit hit = pointer.Cast(eye, 0u, new Vector3(x, y, z));
        PointerHit unit = pointer.Cast(eye, 0u, new Vector3(ux, uy, uz));

        hit.Should().Be(unit, $"direction ({x}, {y}, {z}) points as ({ux}, {uy}, {uz})");
        if (uz < 0f)
        {
            (hit.Hit, hit.Kind).Should().Be((true, SurfaceKind.Terrain), $"{hit}");
            hit.Point.Z.Should().BeApproximately(10f, 1e-4f, $"{hit}");
            hit.Distance.Should().BeApproximately(10f * new Vector3(ux, uy, uz).Length(), 1e-3f, $"{hit}");
        }
        else
        {
            (hit.Hit, hit.Distance).Should().Be((false, Pointer.MaxLength), $"{hit}");
            Vector3.Distance(hit.Point, eye + (Vector3.Normalize(new Vector3(ux, uy, uz)) * Pointer.MaxLength)).Should().BeLessThan(1e-4f, $"the ray's end, 100 m along it: {hit}");
        }
    }

    [Fact]
    public void Cast_ZeroOrNotFiniteDirection_ThrowsNamingIt()
    {
        var pointer = new Pointer(Engine(Heights((_, _) => 10)));
        var eye = new Vector3(96f, 96f, 20f);
        foreach (Vector3 bad in new[] { Vector3.Zero, -Vector3.Zero, new(float.NaN, 0f, 0f), new(0f, float.PositiveInfinity, 0f), new(1f, 0f, float.NegativeInfinity) })
        {
            FluentActions.Invoking(() => pointer.Cast(eye, 0u, bad)).Should().Throw<ArgumentException>().WithParameterName("direction").WithMessage($"*{bad}*");
        }
    }
}
