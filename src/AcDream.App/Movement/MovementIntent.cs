namespace AcDream.App.Movement;

/// <summary>
/// What the player asks for during one frame (keyboard or script), before physics.
/// </summary>
/// <param name="Forward">+1 forward, −1 backward, 0 neither; values in between scale the speed (clamped to −1..1).</param>
/// <param name="Strafe">+1 sideways to the right, −1 to the left (clamped to −1..1).</param>
/// <param name="Turn">+1 turns right (clockwise seen from above), −1 left, at <see cref="PlayerMovementMode.TurnRate"/> (clamped to −1..1).</param>
/// <param name="Run">True: <see cref="PlayerMovementMode.RunSpeed"/>; false: <see cref="PlayerMovementMode.WalkSpeed"/>.</param>
/// <param name="Jump">True: jump at the start of the frame if on the ground (<see cref="PlayerMovementMode.Jump"/>).</param>
public readonly record struct MovementIntent(float Forward, float Strafe, float Turn, bool Run, bool Jump = false);
