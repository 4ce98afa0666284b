using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Body;

/// <summary>Bad body values are rejected where they are given, with an ArgumentException naming the argument.</summary>
public class BodyBadValueTests
{
    [Theory]
    [InlineData(-0.48f, 1.835f, "radius")]
    [InlineData(0f, 1.835f, "radius")]
    [InlineData(float.NaN, 1.835f, "radius")]
    [InlineData(float.PositiveInfinity, 1.835f, "radius")]
    [InlineData(float.NegativeInfinity, 1.835f, "radius")]
    [InlineData(0.48f, -1.835f, "height")]
    [InlineData(0.48f, 0f, "height")]
    [InlineData(0.48f, float.NaN, "height")]
    [InlineData(0.48f, float.PositiveInfinity, "height")]
    [InlineData(0.48f, float.NegativeInfinity, "height")]
    public void MoverBody_BadSize_ThrowsNamingIt(float radius, float height, string name)
    {
        FluentActions.Invoking(() => new MoverBody(radius, height))
            .Should().Throw<ArgumentException>().WithParameterName(name).Which.Message.Should().Contain("finite");
    }

    [Fact]
    public void MovementOptions_DefaultBody_ThrowsNamingBody()
    {
        // default(MoverBody) has a zero radius and height: as an option it is an error, not a point.
        FluentActions.Invoking(() => new MovementOptions { Body = default(MoverBody) })
            .Should().Throw<ArgumentException>().WithParameterName("Body").Which.Message.Should().Contain("default(MoverBody)");
        FluentActions.Invoking(() => new MovementOptions { Body = new MoverBody() })
            .Should().Throw<ArgumentException>().WithParameterName("Body");
        FluentActions.Invoking(() => MovementOptions.Player with { Body = default(MoverBody) })
            .Should().Throw<ArgumentException>().WithParameterName("Body");
    }

    [Fact]
    public void MovementOptions_GoodOrNoBody_Accepted()
    {
        new MovementOptions { Body = null }.Body.Should().BeNull();
        new MovementOptions { Body = new MoverBody(1e-6f, 1e-6f) }.Body.Should().Be(new MoverBody(1e-6f, 1e-6f));
        MovementOptions.Player.Body.Should().Be(new MoverBody(0.48f, 1.835f), "the player's body: radius 0.48 m, 1.835 m tall");
        (MovementOptions.Player with { Body = null }).Body.Should().BeNull();
    }
}
